#include "calib/sim/optics/OpticsCell.h"

namespace omnitune {

std::string opticsLightName(OpticsLight light)
{
    switch (light) {
    case OpticsLight::Dim: return "dim";
    case OpticsLight::Normal: return "normal";
    case OpticsLight::Bright: return "bright";
    case OpticsLight::Uneven: return "uneven";
    }
    return "normal";
}

std::string opticsDistractorsName(OpticsDistractors distractors)
{
    switch (distractors) {
    case OpticsDistractors::None: return "none";
    case OpticsDistractors::RobotsFeetShadow: return "robots";
    case OpticsDistractors::NoiseBlur: return "noise";
    case OpticsDistractors::RodsOcclusion: return "rods";
    }
    return "none";
}

std::string opticsCarpetName(OpticsCarpet carpet)
{
    switch (carpet) {
    case OpticsCarpet::Green: return "green";
    case OpticsCarpet::CyanGreen: return "cyan-green";
    case OpticsCarpet::DarkGreen: return "dark-green";
    }
    return "green";
}

std::string opticsMirrorName(OpticsMirror mirror)
{
    return mirror == OpticsMirror::Spherical ? "spherical" : "hyperbolic";
}

std::string opticsCellName(const OpticsCell& cell)
{
    std::string name = std::string(ballKindName(cell.ball)) + "/" + opticsLightName(cell.light) + "/" +
                       opticsDistractorsName(cell.distractors) + "/" + std::to_string(cell.image.width) + "x" +
                       std::to_string(cell.image.height);
    if (cell.carpet != OpticsCarpet::Green) name += "/" + opticsCarpetName(cell.carpet);
    if (cell.mirror != OpticsMirror::Hyperbolic) name += "/" + opticsMirrorName(cell.mirror);
    if (!cell.ballPresent) name += "/no-ball";
    return name;
}

// Stub until the renderer lands: empty frames of the cell's size, no ball.
OpticsCellFrames renderCell(const OpticsCell& cell, const Config& base)
{
    OpticsCellFrames out;
    out.fittedConfig = base;
    for (int i = 0; i < cell.frames; ++i) {
        out.frames.push_back(cv::Mat(cell.image, CV_8UC3, cv::Scalar(40, 120, 40)));
        TruthRow row;
        row.frame = i;
        out.truth[i] = row;
    }
    return out;
}

}  // namespace omnitune
