#include "calib/colour/AutoColour.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace omnitune {

namespace {

// Hue offset of h from `centre` on the hue circle, -90..89.
int hueOffset(int h, int centre) { return ((h - centre + 270) % 180) - 90; }
int wrapHue(int h) { return ((h % 180) + 180) % 180; }

template <class T>
T percentile(std::vector<T> v, double pct)
{
    const std::size_t i = std::min(v.size() - 1, std::size_t(std::lround(pct / 100.0 * double(v.size() - 1))));
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(i), v.end());
    return v[i];
}

// Takes the carpet's hues [lo, hi] (no wrap) out of a non-wrapping class range; says what it did.
void trimOff(HsvRange& r, int lo, int hi, const std::string& name, std::vector<std::string>& notes)
{
    if (!r.enabled || r.hMin > r.hMax || lo > hi || r.hMax < lo || r.hMin > hi) return;
    const std::string was = std::to_string(r.hMin) + ".." + std::to_string(r.hMax);
    if (r.hMin >= lo && r.hMax <= hi) {
        r.enabled = false;
        notes.push_back(name + " hue " + was + " disabled (the carpet's)");
        return;
    }
    if (r.hMin < lo) r.hMax = lo - 1;
    else r.hMin = hi + 1;
    notes.push_back(name + " hue " + was + " -> " + std::to_string(r.hMin) + ".." + std::to_string(r.hMax) +
                    " (off the carpet's)");
}

}  // namespace

AutoColourResult autoColour(const std::vector<cv::Mat>& frames, const Geometry& geometry, const ColorLutOptions& start,
                            const AutoColourOptions& o)
{
    AutoColourResult res;
    res.colors = start;
    // What is set follows the classes' roles: the first field class is the carpet, the first
    // black and line classes black and white.
    auto firstWith = [&res](ColourRole role) -> ColourClassDef* {
        for (ColourClassDef& c : res.colors.classes)
            if (c.role == role) return &c;
        return nullptr;
    };
    if (!firstWith(ColourRole::Field)) {
        res.error = "no class has role field: there is no carpet class to calibrate";
        return res;
    }
    if (frames.empty()) {
        res.error = "no frames to calibrate colour from";
        return res;
    }
    // HSV of every sampled used pixel of every frame.
    std::vector<cv::Vec3b> samples;
    cv::Mat bgr;
    cv::Mat hsv;
    const int step = std::max(1, o.sampleStep);
    for (const cv::Mat& f : frames) {
        if (f.size() != geometry.imageSize() || (f.type() != CV_8UC3 && f.type() != CV_8UC2)) {
            res.error = "a frame is " + std::to_string(f.cols) + "x" + std::to_string(f.rows) + " with " +
                        std::to_string(f.channels()) + " channel(s); the geometry needs " +
                        std::to_string(geometry.imageSize().width) + "x" + std::to_string(geometry.imageSize().height) +
                        " BGR or UYVY frames";
            return res;
        }
        if (f.type() == CV_8UC2)
            convertUyvyToBgr(f, bgr);
        else
            bgr = f;
        cv::cvtColor(bgr, hsv, cv::COLOR_BGR2HSV);
        for (const RowSpan& s : geometry.spans()) {
            if (s.y % step) continue;
            const cv::Vec3b* row = hsv.ptr<cv::Vec3b>(s.y);
            for (int x = s.x0 + (step - s.x0 % step) % step; x < s.x1; x += step) samples.push_back(row[x]);
        }
    }
    if (samples.empty()) {
        res.error = "the geometry uses no pixels (check the radii and the mask)";
        return res;
    }

    // The dominant hue among pixels with a reliable hue, on a lightly smoothed histogram.
    std::array<int, 180> hist{};
    for (const cv::Vec3b& p : samples)
        if (p[1] >= o.minSaturation && p[2] >= o.minValue) ++hist[p[0]];
    std::array<int, 180> smooth{};
    for (int h = 0; h < 180; ++h)
        for (int k = -2; k <= 2; ++k) smooth[std::size_t(h)] += hist[std::size_t(wrapHue(h + k))];
    const int smoothPeak = int(std::max_element(smooth.begin(), smooth.end()) - smooth.begin());
    // The smoothed maximum is a plateau for a narrow carpet: take the raw maximum inside it.
    int peak = smoothPeak;
    for (int k = -2; k <= 2; ++k)
        if (hist[std::size_t(wrapHue(smoothPeak + k))] > hist[std::size_t(peak)]) peak = wrapHue(smoothPeak + k);
    if (smooth[std::size_t(smoothPeak)] == 0) {
        res.error = "no pixel in the used area has a colour (all grey, black or white): is the camera's image there?";
        return res;
    }
    // The carpet's hue band: where the histogram stays above peakSharePct of the peak.
    const double floorCount = o.peakSharePct / 100.0 * smooth[std::size_t(smoothPeak)];
    int below = 0;
    while (below < 45 && smooth[std::size_t(wrapHue(peak - below - 1))] >= floorCount) ++below;
    int above = 0;
    while (above < 45 && smooth[std::size_t(wrapHue(peak + above + 1))] >= floorCount) ++above;

    if (below + above + 1 > o.maxHueBand) {
        res.error = "no dominant hue: the colours in the used area spread over " + std::to_string(below + above + 1) +
                    " hue steps around " + std::to_string(peak) + " (a carpet spans at most " +
                    std::to_string(o.maxHueBand) + "): is the carpet in view, and the geometry set?";
        return res;
    }
    std::vector<int> offsets;
    std::vector<int> sats;
    std::vector<int> values;
    for (const cv::Vec3b& p : samples) {
        if (p[1] < o.minSaturation || p[2] < o.minValue) continue;
        const int d = hueOffset(p[0], peak);
        if (d < -below || d > above) continue;
        offsets.push_back(d);
        sats.push_back(p[1]);
        values.push_back(p[2]);
    }
    res.carpetHue = peak;
    res.carpetPct = 100.0 * double(offsets.size()) / double(samples.size());
    if (res.carpetPct < o.minCarpetPct) {
        res.error = "the dominant hue (" + std::to_string(peak) + ") covers only " +
                    std::to_string(int(std::lround(res.carpetPct))) + " % of the used area (at least " +
                    std::to_string(int(o.minCarpetPct)) + " % needed): is the carpet in view, and the geometry set?";
        return res;
    }
    res.carpetV = percentile(values, 50.0);

    // Green: the carpet's hue spread (tails cut) plus a margin; saturation down to a bit below its
    // low tail; V from just above black (unused with relative black, which follows the carpet).
    const int hLo = percentile(offsets, o.tailPct) - o.hueMarginDeg;
    const int hHi = percentile(offsets, 100.0 - o.tailPct) + o.hueMarginDeg;
    const int sLow = percentile(sats, o.tailPct);
    res.carpetS = percentile(sats, 50.0);
    const int blackV = std::clamp(int(std::lround(o.blackVRatio * res.carpetV)), 1, 254);
    ColourClassDef& field = *firstWith(ColourRole::Field);
    // S floor: not below minSaturationShare of the median either: pixels where the ball's border
    // blurs into the carpet are greenish with low S, and calling them carpet eats the ball's rim
    // (simulated dim tours: S floor 31 -> 60-85 % of balls, 60..110 -> 100 %).
    const int sMin = std::max({10, int(0.8 * sLow), int(std::lround(o.minSaturationShare * res.carpetS))});
    field.enabled = true;
    field.boxes = {HsvRange{true, wrapHue(peak + hLo), wrapHue(peak + hHi), std::min(sMin, 250), 255, blackV + 1, 255}};
    const HsvRange green = field.boxes.front();
    // One dominant hue says nothing about a second carpet region: the other enabled field classes
    // keep their boxes (the user sampled them on purpose), and the note says so.
    for (const ColourClassDef& c : res.colors.classes)
        if (&c != &field && c.enabled && c.role == ColourRole::Field)
            res.notes.push_back("field class " + c.name + " kept as it was (one carpet hue was found, set in " + field.name +
                                "): sample the other carpet region into it");

    // Black: dark relative to the carpet, any hue.
    res.colors.blackRelative = true;
    res.colors.blackVRatio = o.blackVRatio;
    if (ColourClassDef* black = firstWith(ColourRole::Black)) {
        black->enabled = true;
        black->boxes = {HsvRange{true, 0, 179, 0, 255, 0, blackV}};
    } else {
        res.notes.push_back("no class has role black: robots stay unclassified");
    }

    // White: low saturation (below green's), clearly brighter than the carpet.
    const int whiteSMax = std::clamp(green.sMin - 1, 10, 60);
    const int whiteVMin = std::clamp(int(std::lround(std::min(1.3 * res.carpetV, (res.carpetV + 255) / 2.0))),
                                     blackV + 1, 250);
    if (ColourClassDef* white = firstWith(ColourRole::Line)) {
        white->enabled = true;
        white->boxes = {HsvRange{true, 0, 179, 0, whiteSMax, whiteVMin, 255}};
    } else {
        res.notes.push_back("no class has role line: lines stay unclassified");
    }

    // The ball's and the markers' colours are seen in the same light as the carpet: a saturated
    // hue brighter than black is theirs however dim the hall (the defaults' V floor of 80 left a
    // dim tour's orange ball, V ~55, in no class, merging it with a shadowed line).
    for (ColourClassDef& c : res.colors.classes) {
        if (!c.enabled || c.role == ColourRole::Field || c.role == ColourRole::Black || c.role == ColourRole::Line) continue;
        for (HsvRange& box : c.boxes)
            if (box.enabled && box.vMin > blackV + 1 && box.vMin <= box.vMax) box.vMin = std::min(box.vMax, blackV + 1);
    }

    // Colour classes after the carpet in priority order never see the carpet's hues anyway; trim
    // them so that their boxes say what they do (a cyan-green carpet overlaps the cyan marker class).
    if (green.hMin <= green.hMax) {
        bool after = false;
        for (ColourClassDef& c : res.colors.classes) {
            after = after || &c == &field;
            if (!after || !c.enabled || c.role == ColourRole::Field || c.role == ColourRole::Black ||
                c.role == ColourRole::Line)
                continue;
            for (HsvRange& box : c.boxes) trimOff(box, green.hMin, green.hMax, c.name, res.notes);
        }
    }
    return res;
}

}  // namespace omnitune
