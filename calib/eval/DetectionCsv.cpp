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
        // Within a tier, the scores every candidate of that tier has measured: a colour refusal's
        // shape is measured only when the pipeline explains its rejections.
        const bool shape = c.rejected != RejectReason::NonGreen && c.rejected != RejectReason::NonBlack;
        const double s = c.scores.nonGreenPct + c.scores.nonBlackPct + (shape ? c.scores.circularityPct : 0.0);
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

// A percentage as the CSV writes it: one decimal.
std::string percentField(double pct)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f", pct);
    return buf;
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
        // A score the pipeline did not measure (Pipeline::setExplainRejections) is left empty.
        const auto score = [](bool measured, double pct) { return measured ? percentField(pct) : std::string(); };
        const ValidationScores& s = c->scores;
        row += "," + score(s.squareMeasured, s.nonGreenPct) + "," + score(s.squareMeasured, s.nonBlackPct) + "," +
               score(s.shapeMeasured, s.circularityPct) + "," + std::string(candidateSourceName(c->source)) + "," +
               csvField(std::string(rejectReasonName(c->rejected)));
    } else {
        row += ",,,,,";
    }
    return row + "," + csvField(r.error);
}

}  // namespace omnitune
