#pragma once
// Why a geometry fit refused to give a result: a kind the caller can act on (the window offers
// "use more frames", the tool exits non-zero) and one sentence that says what is wrong and what
// to do. Fits never print; they return this.
#include <string>
#include <string_view>

namespace omnitune {

enum class FitErrorKind {
    BadInput,       // frames of different sizes or types, a point with a negative value, ...
    Uniform,        // the frames show no contrast (all black, all one grey)
    NoRim,          // no boundary between a bright mirror image and a dark outside
    TooFewFrames,   // the robot body needs several frames
    StaticField,    // the field did not move between the frames, so the body cannot be told apart
    TooFewPoints,   // fewer points or samples than the model needs
    NarrowSpan,     // the samples cover too little distance to fix the curve
    NotMonotone,    // the fitted distance map bends back inside the used radii
    OutOfRange,     // the fitted curve gives impossible values (a negative distance or radius)
    Cancelled,      // Progress::isCancelRequested() said stop
};

std::string_view fitErrorKindName(FitErrorKind kind);

struct FitError {
    FitErrorKind kind = FitErrorKind::BadInput;
    std::string message;  // what is wrong and what to do, one line

    std::string toString() const { return message; }
};

}  // namespace omnitune
