#include "calib/eval/DetectionCsv.h"

#include <cstdio>

namespace omnitune {

namespace {

// The candidate shown in the row: the chosen one, else the one that passed most tests.
const BallCandidate* decisiveCandidate(const PipelineResult& r)
{
    if (r.detection.found) return &r.candidates[std::size_t(r.detection.candidate)];
    const BallCandidate* best = nullptr;
    auto rank = [](const BallCandidate& c) {
        const double s = c.scores.nonGreenPct + c.scores.nonBlackPct + c.scores.circularityPct;
        switch (c.rejected) {
        case RejectReason::RunsOn:
        case RejectReason::LineJunction:
        case RejectReason::LineBlob: return 4000 + s;
        case RejectReason::Circularity: return 3000 + s;
        case RejectReason::NonBlack: return 2000 + s;
        case RejectReason::NonGreen: return 1000 + s;
        default: return s;
        }
    };
    for (const auto& c : r.candidates)
        if (!best || rank(c) > rank(*best)) best = &c;
    return best;
}

}  // namespace

std::string csvField(const std::string& s)
{
    if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
    std::string out = "\"";
    for (char ch : s) out += ch == '"' ? std::string("\"\"") : std::string(1, ch == '\n' || ch == '\r' ? ' ' : ch);
    return out + "\"";
}

std::string detectionCsvHeader()
{
    return "frame,found,px,py,radius_px,x_m,y_m,time_ms,candidates,non_green_pct,non_black_pct,circularity_pct,"
           "source,rejected,error";
}

std::string detectionCsvRow(int frame, const PipelineResult& r)
{
    char buf[512];
    const BallDetection& d = r.detection;
    std::snprintf(buf, sizeof buf, "%d,%d,%.2f,%.2f,%.2f,%.4f,%.4f,%.3f,%zu", frame, d.found ? 1 : 0, d.px, d.py,
                  d.radiusPx, d.xM, d.yM, r.timings.totalMs, r.candidates.size());
    std::string row = buf;
    if (const BallCandidate* c = decisiveCandidate(r)) {
        std::snprintf(buf, sizeof buf, ",%.1f,%.1f,%.1f,%s,%s", c->scores.nonGreenPct, c->scores.nonBlackPct,
                      c->scores.circularityPct, std::string(candidateSourceName(c->source)).c_str(),
                      csvField(std::string(rejectReasonName(c->rejected))).c_str());
        row += buf;
    } else {
        row += ",,,,,";
    }
    return row + "," + csvField(r.error);
}

}  // namespace omnitune
