#include "calib/fit/FitError.h"

namespace omnitune {

std::string_view fitErrorKindName(FitErrorKind kind)
{
    switch (kind) {
    case FitErrorKind::BadInput: return "bad input";
    case FitErrorKind::Uniform: return "uniform frames";
    case FitErrorKind::NoRim: return "no rim";
    case FitErrorKind::TooFewFrames: return "too few frames";
    case FitErrorKind::StaticField: return "static field";
    case FitErrorKind::TooFewPoints: return "too few points";
    case FitErrorKind::NarrowSpan: return "narrow span";
    case FitErrorKind::NotMonotone: return "not monotone";
    case FitErrorKind::OutOfRange: return "out of range";
    case FitErrorKind::Cancelled: return "cancelled";
    }
    return "?";
}

}  // namespace omnitune
