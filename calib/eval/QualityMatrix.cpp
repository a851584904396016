#include "calib/eval/QualityMatrix.h"

#include <algorithm>

namespace omnitune {

namespace {

constexpr OpticsLight kLights[] = {OpticsLight::Dim, OpticsLight::Normal, OpticsLight::Bright, OpticsLight::Uneven};
constexpr OpticsDistractors kDistractors[] = {OpticsDistractors::None, OpticsDistractors::RobotsFeetShadow,
                                              OpticsDistractors::NoiseBlur, OpticsDistractors::RodsOcclusion};
constexpr OpticsCarpet kCarpets[] = {OpticsCarpet::Green, OpticsCarpet::CyanGreen, OpticsCarpet::DarkGreen};

}  // namespace

std::vector<OpticsCell> qualityMatrixCells(const QualityMatrixOptions& options)
{
    std::vector<OpticsCell> cells;
    unsigned index = 0;
    auto add = [&](OpticsCell cell, std::size_t carpetTurn) {
        cell.carpet = kCarpets[carpetTurn % std::size(kCarpets)];
        // Distinct, reproducible seeds: a cell's frames do not depend on which other cells run.
        cell.seed = options.seed * 1000003u + index++;
        cell.directions = options.directions;
        cells.push_back(cell);
    };
    for (const cv::Size& size : options.sizes) {
        const OpticsMirror mirror = size.width == size.height ? OpticsMirror::Spherical : OpticsMirror::Hyperbolic;
        for (std::size_t l = 0; l < std::size(kLights); ++l)
            for (std::size_t d = 0; d < std::size(kDistractors); ++d)
                for (std::size_t b = 0; b < kExtendedBallKinds.size(); ++b) {
                    OpticsCell cell;
                    cell.ball = kExtendedBallKinds[b];
                    cell.light = kLights[l];
                    cell.distractors = kDistractors[d];
                    cell.mirror = mirror;
                    cell.image = size;
                    cell.frames = options.framesPerCell;
                    add(cell, b + l + d);
                }
    }
    if (options.ballFreeCells)
        for (const cv::Size& size : options.sizes) {
            const OpticsMirror mirror = size.width == size.height ? OpticsMirror::Spherical : OpticsMirror::Hyperbolic;
            for (std::size_t l = 0; l < std::size(kLights); ++l)
                for (std::size_t d = 0; d < std::size(kDistractors); ++d) {
                    OpticsCell cell;
                    cell.ballPresent = false;
                    cell.light = kLights[l];
                    cell.distractors = kDistractors[d];
                    cell.mirror = mirror;
                    cell.image = size;
                    cell.frames = options.ballFreeFramesPerCell;
                    add(cell, l + d);
                }
        }
    return cells;
}

std::vector<OpticsCell> filterOpticsCells(const std::vector<OpticsCell>& cells, const std::string& parts)
{
    std::vector<std::string> wanted;
    std::size_t start = 0;
    while (start <= parts.size()) {
        const std::size_t comma = std::min(parts.find(',', start), parts.size());
        if (comma > start) wanted.push_back(parts.substr(start, comma - start));
        start = comma + 1;
    }
    std::vector<OpticsCell> out;
    for (const OpticsCell& c : cells) {
        const std::string name = opticsCellName(c);
        bool all = true;
        for (const std::string& w : wanted) all = all && name.find(w) != std::string::npos;
        if (all) out.push_back(c);
    }
    return out;
}

}  // namespace omnitune
