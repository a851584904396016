#pragma once
// A PI controller in velocity form: each update returns the change of the output,
//     du = kp * (e_k - e_{k-1}) + ki * e_k,
// so the output is the camera's register itself and a feature clamped at its limit does not
// wind an integral up. When the error changes sign (an overshoot) the step is the integral
// part alone: the proportional part would double the step back, and on a scene more sensitive
// than the gains assume that kick makes the loop hunt around the target instead of settling.
namespace omnitune {

class PiController {
public:
    PiController(double kp = 0.0, double ki = 0.0) : kp_(kp), ki_(ki) {}

    double update(double error)
    {
        const bool crossed = started_ && (error > 0) != (last_ > 0);
        const double du = kp_ * (error - (started_ && !crossed ? last_ : error)) + ki_ * error;
        last_ = error;
        started_ = true;
        return du;
    }
    void reset() { started_ = false; }

private:
    double kp_ = 0.0, ki_ = 0.0;
    double last_ = 0.0;
    bool started_ = false;
};

}  // namespace omnitune
