#include "calib/colour/BoxFit.h"

#include "calib/colour/HueArc.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace omnitune {

namespace {

// Samples ignored at each end of a channel's spread.
int outlierCount(std::size_t n, double pct)
{
    const double p = std::clamp(pct, 0.0, 25.0);
    return int(std::floor(double(n) * p / 100.0));
}

// The shortest arc holding at least `keep` of the hues (ties: the one holding most).
HueArc shortestArc(const std::vector<int>& hues, int keep)
{
    std::array<int, kHueSteps> count{};
    for (int h : hues) ++count[std::size_t(wrapHue(h))];
    HueArc best{0, kHueSteps};
    int bestHeld = 0;
    for (int start = 0; start < kHueSteps; ++start) {
        if (count[std::size_t(start)] == 0) continue;  // a shortest arc starts on a sample
        int held = 0;
        for (int len = 1; len <= best.length; ++len) {
            held += count[std::size_t(wrapHue(start + len - 1))];
            if (held >= keep) {
                if (len < best.length || held > bestHeld) {
                    best = {start, len};
                    bestHeld = held;
                }
                break;
            }
        }
    }
    return best;
}

std::pair<int, int> trimmedSpan(std::vector<int> v, int cut)
{
    std::sort(v.begin(), v.end());
    return {v[std::size_t(cut)], v[v.size() - 1 - std::size_t(cut)]};
}

}  // namespace

long long boxVolume(const HsvRange& box)
{
    if (!box.enabled || box.sMin > box.sMax || box.vMin > box.vMax) return 0;
    return (long long)HueArc::of(box).length * (box.sMax - box.sMin + 1) * (box.vMax - box.vMin + 1);
}

std::optional<HsvRange> fitBox(const std::vector<Hsv>& samples, const BoxFitOptions& o)
{
    if (samples.empty()) return std::nullopt;
    const int cut = outlierCount(samples.size(), o.outlierPct);
    std::vector<int> h, s, v;
    h.reserve(samples.size());
    s.reserve(samples.size());
    v.reserve(samples.size());
    for (const Hsv& p : samples) {
        h.push_back(p.h);
        s.push_back(p.s);
        v.push_back(p.v);
    }
    HsvRange box;
    HueArc arc = shortestArc(h, int(samples.size()) - 2 * cut);
    if (arc.length > o.fullHueAbove) arc = HueArc{0, kHueSteps};
    arc.applyTo(box);
    std::tie(box.sMin, box.sMax) = trimmedSpan(std::move(s), cut);
    std::tie(box.vMin, box.vMax) = trimmedSpan(std::move(v), cut);
    return box;
}

HsvRange growBox(const HsvRange& box, const std::vector<Hsv>& samples, const BoxFitOptions& o)
{
    const std::optional<HsvRange> add = fitBox(samples, o);
    if (!add) return box;
    if (!box.enabled) return *add;
    HsvRange out = box;
    unite(HueArc::of(box), HueArc::of(*add)).applyTo(out);
    out.sMin = std::min(box.sMin, add->sMin);
    out.sMax = std::max(box.sMax, add->sMax);
    out.vMin = std::min(box.vMin, add->vMin);
    out.vMax = std::max(box.vMax, add->vMax);
    return out;
}

BoxCut cutBox(const HsvRange& box, const std::vector<Hsv>& samples, const BoxFitOptions& o)
{
    BoxCut res;
    res.box = box;
    std::vector<Hsv> inside;
    for (const Hsv& p : samples)
        if (box.contains(p.h, p.s, p.v)) inside.push_back(p);
    if (inside.empty()) return res;
    res.changed = true;

    const HueArc arc = HueArc::of(box);
    std::vector<int> hOff, s, v;
    for (const Hsv& p : inside) {
        hOff.push_back(arc.offsetOf(p.h));
        s.push_back(p.s);
        v.push_back(p.v);
    }
    const int cut = outlierCount(inside.size(), o.outlierPct);
    const auto [hLo, hHi] = trimmedSpan(hOff, cut);
    const auto [sLo, sHi] = trimmedSpan(s, cut);
    const auto [vLo, vHi] = trimmedSpan(v, cut);

    // The six one-sided cuts; the one keeping most volume wins.
    std::vector<HsvRange> options;
    auto withArc = [&](HueArc a) {
        HsvRange r = box;
        if (a.length <= 0) {
            r.sMin = 1;  // empty: volume 0
            r.sMax = 0;
            return r;
        }
        r.hMin = a.start;
        r.hMax = wrapHue(a.start + a.length - 1);
        return r;
    };
    if (arc.full()) {
        // Every hue: the cut leaves the arc outside the samples' own shortest arc.
        std::vector<int> hues;
        for (const Hsv& p : inside) hues.push_back(p.h);
        const HueArc taken = shortestArc(hues, int(inside.size()) - 2 * cut);
        options.push_back(withArc(HueArc{wrapHue(taken.start + taken.length), kHueSteps - taken.length}));
    } else {
        options.push_back(withArc(HueArc{wrapHue(arc.start + hHi + 1), arc.length - hHi - 1}));
        options.push_back(withArc(HueArc{arc.start, hLo}));
    }
    HsvRange r = box;
    r.sMin = sHi + 1;
    options.push_back(r);
    r = box;
    r.sMax = sLo - 1;
    options.push_back(r);
    r = box;
    r.vMin = vHi + 1;
    options.push_back(r);
    r = box;
    r.vMax = vLo - 1;
    options.push_back(r);

    const auto best = std::max_element(options.begin(), options.end(),
                                       [](const HsvRange& a, const HsvRange& b) { return boxVolume(a) < boxVolume(b); });
    if (boxVolume(*best) == 0) res.box.reset();
    else res.box = *best;
    for (const Hsv& p : inside)
        if (!res.box || !res.box->contains(p.h, p.s, p.v)) ++res.removedSamples;
    return res;
}

}  // namespace omnitune
