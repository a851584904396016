#pragma once
// Comparing two colour calibrations (venue profiles, or a profile and the current config): their
// classes side by side, and the pixels of a frame that change class from one to the other
// (classes matched by name: ids may differ between two lists).
#include "core/ColorLut.h"
#include "core/Geometry.h"
#include "core/PixelFormat.h"

#include <opencv2/core.hpp>

#include <string>
#include <vector>

namespace omnitune {

// One line of the side-by-side view: a setting or a class, as each calibration has it.
struct ColourDiffRow {
    std::string what;   // "lut_bits", "class green"
    std::string left;   // "-" when the left calibration lacks it
    std::string right;
    bool same = false;
};

// The settings (lut_bits, black_relative, black_v_ratio) and every class of either side, the
// left's classes in their order, then those only the right has. A class reads "field, on,
// #2: H 35..85 S 60..255 V 40..255" (role, enabled, priority, boxes joined by " + ").
std::vector<ColourDiffRow> diffColourCalibrations(const ColorLutOptions& left, const ColorLutOptions& right);

// The rows as aligned text columns under a header naming both sides, a '*' marking the rows
// that differ.
std::string formatColourDiff(const std::vector<ColourDiffRow>& rows, const std::string& leftName,
                             const std::string& rightName);

struct ClassChanges {
    int processed = 0;  // pixels the geometry processes
    int changed = 0;    // of those, pixels whose class name differs
    cv::Mat mask;       // CV_8UC1, 255 where the class changes
    double share() const { return processed > 0 ? double(changed) / processed : 0.0; }
};

// Segments `frame` (of the geometry's size) with both calibrations, as the detector does (the
// frame's carpet for relative black), and compares the class names pixel by pixel.
ClassChanges classChanges(const cv::Mat& frame, PixelFormat format, const Geometry& geometry,
                          const ColorLutOptions& left, const ColorLutOptions& right);

// The changes for the eye: `bgr` (the frame, CV_8UC3) dimmed to `dim` of its brightness, the
// pixels of `changed` (CV_8UC1, 255 = changes class) in magenta over it, each drawn as a disc of
// `markRadius` px so that thin changes (a box edge along the lines) survive a scaled-down view.
cv::Mat classChangeImage(const cv::Mat& bgr, const cv::Mat& changed, double dim = 0.35, int markRadius = 0);

}  // namespace omnitune
