#pragma once
// std::lround's rounding (halves away from zero) inline: glibc's lround is a library call, and the
// validation's pixel walks round two coordinates per half-pixel step (the green-panel walk alone
// was a tenth of a hard frame's time in it). Exact for |v| < 2^31: the truncation and the
// fraction v - trunc(v) are both exact in double.
namespace omnitune {

inline int roundHalfAway(double v)
{
    const int t = int(v);  // toward zero
    const double fraction = v - double(t);
    return fraction >= 0.5 ? t + 1 : fraction <= -0.5 ? t - 1 : t;
}

}  // namespace omnitune
