#include "calib/colour/ColourProfileDiff.h"

#include "core/YamlText.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <array>
#include <sstream>

namespace omnitune {

namespace {

std::string boxText(const HsvRange& b)
{
    return "H " + std::to_string(b.hMin) + ".." + std::to_string(b.hMax) + " S " + std::to_string(b.sMin) + ".." +
           std::to_string(b.sMax) + " V " + std::to_string(b.vMin) + ".." + std::to_string(b.vMax) +
           (b.enabled ? "" : " (off)");
}

std::string classText(const ColourClasses& classes, int index)
{
    if (index < 0) return "-";
    const ColourClassDef& c = classes[std::size_t(index)];
    std::string s = std::string(colourRoleName(c.role)) + ", " + (c.enabled ? "on" : "off") + ", #" +
                    std::to_string(index + 1) + ":";
    for (std::size_t i = 0; i < c.boxes.size(); ++i) s += (i ? " + " : " ") + boxText(c.boxes[i]);
    return s;
}

}  // namespace

std::vector<ColourDiffRow> diffColourCalibrations(const ColorLutOptions& left, const ColorLutOptions& right)
{
    std::vector<ColourDiffRow> rows;
    auto add = [&rows](std::string what, std::string l, std::string r) {
        const bool same = l == r;
        rows.push_back({std::move(what), std::move(l), std::move(r), same});
    };
    add("lut_bits", std::to_string(left.bits), std::to_string(right.bits));
    add("black_relative", left.blackRelative ? "on" : "off", right.blackRelative ? "on" : "off");
    add("black_v_ratio", yamlNumber(left.blackVRatio), yamlNumber(right.blackVRatio));
    for (int i = 0; i < int(left.classes.size()); ++i) {
        const std::string& name = left.classes[std::size_t(i)].name;
        add("class " + name, classText(left.classes, i), classText(right.classes, findColourClass(right.classes, name)));
    }
    for (int i = 0; i < int(right.classes.size()); ++i) {
        const std::string& name = right.classes[std::size_t(i)].name;
        if (findColourClass(left.classes, name) < 0) add("class " + name, "-", classText(right.classes, i));
    }
    return rows;
}

std::string formatColourDiff(const std::vector<ColourDiffRow>& rows, const std::string& leftName,
                             const std::string& rightName)
{
    std::size_t whatWidth = 4;
    std::size_t leftWidth = leftName.size();
    for (const ColourDiffRow& r : rows) {
        whatWidth = std::max(whatWidth, r.what.size());
        leftWidth = std::max(leftWidth, r.left.size());
    }
    auto pad = [](const std::string& s, std::size_t w) { return s + std::string(w > s.size() ? w - s.size() : 0, ' '); };
    std::ostringstream out;
    out << "  " << pad("", whatWidth) << "  " << pad(leftName, leftWidth) << "  " << rightName << "\n";
    for (const ColourDiffRow& r : rows)
        out << (r.same ? "  " : "* ") << pad(r.what, whatWidth) << "  " << pad(r.left, leftWidth) << "  " << r.right << "\n";
    return out.str();
}

ClassChanges classChanges(const cv::Mat& frame, PixelFormat format, const Geometry& geometry,
                          const ColorLutOptions& left, const ColorLutOptions& right)
{
    CV_Assert(frame.size() == geometry.imageSize());
    cv::Mat a(frame.size(), CV_8UC1, cv::Scalar(0));
    cv::Mat b(frame.size(), CV_8UC1, cv::Scalar(0));
    ColorLut(left).segment(frame, format, geometry.spans(), a);
    ColorLut(right).segment(frame, format, geometry.spans(), b);
    // Class id -> the right's id of the same name (-1: the right has no such class).
    std::array<int, 256> same;
    same.fill(-1);
    same[0] = 0;
    for (int i = 0; i < int(left.classes.size()); ++i)
        if (const int j = findColourClass(right.classes, left.classes[std::size_t(i)].name); j >= 0) same[std::size_t(i + 1)] = j + 1;
    ClassChanges out;
    out.mask = cv::Mat(frame.size(), CV_8UC1, cv::Scalar(0));
    for (const RowSpan& s : geometry.spans()) {
        const std::uint8_t* pa = a.ptr<std::uint8_t>(s.y);
        const std::uint8_t* pb = b.ptr<std::uint8_t>(s.y);
        std::uint8_t* m = out.mask.ptr<std::uint8_t>(s.y);
        for (int x = s.x0; x < s.x1; ++x) {
            ++out.processed;
            if (same[pa[x]] != int(pb[x])) {
                m[x] = 255;
                ++out.changed;
            }
        }
    }
    return out;
}

cv::Mat classChangeImage(const cv::Mat& bgr, const cv::Mat& changed, double dim, int markRadius)
{
    CV_Assert(bgr.type() == CV_8UC3 && changed.type() == CV_8UC1 && bgr.size() == changed.size());
    cv::Mat out;
    bgr.convertTo(out, -1, dim);
    cv::Mat marks = changed;
    if (markRadius > 0)
        cv::dilate(changed, marks, cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * markRadius + 1, 2 * markRadius + 1)));
    out.setTo(cv::Scalar(255, 0, 255), marks);
    return out;
}

}  // namespace omnitune
