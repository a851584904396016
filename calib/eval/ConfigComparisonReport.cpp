#include "calib/eval/ConfigComparisonReport.h"

#include <cstdio>

namespace omnitune {

namespace {

std::string row(const std::string& name, const std::vector<FrameOutcome>& outcomes, const EvaluationRow& r,
                bool hasTruth)
{
    char buf[512];
    const int found = detectionCount(outcomes);
    const double foundPct = r.frames ? 100.0 * found / r.frames : 0.0;
    std::string ratio = "n/a", falsePositives = "n/a";  // without truth there is nothing to judge against
    if (hasTruth) {
        std::snprintf(buf, sizeof buf, "%.1f (%d / %d)", r.detectionRatioPct, r.correct, r.withBall);
        ratio = buf;
        std::snprintf(buf, sizeof buf, "%d (%.1f %%)", r.falsePositives, r.falsePositivePct);
        falsePositives = buf;
    }
    std::snprintf(buf, sizeof buf, "| %s | %d | %d | %d (%.1f %%) | %s | %s | %.1f |\n", name.c_str(), r.frames,
                  r.failed, found, foundPct, ratio.c_str(), falsePositives.c_str(), r.timeAvgMs);
    return buf;
}

std::string frameList(const SessionComparison& c, FrameChange kind)
{
    std::string text;
    for (const FrameComparison& f : c.frames) {
        if (f.change != kind) continue;
        text += (text.empty() ? "" : " ") + std::to_string(f.frame);
        if (kind == FrameChange::Moved) {
            char buf[32];
            std::snprintf(buf, sizeof buf, " (%.0f px)", f.shiftPx);
            text += buf;
        }
    }
    return text.empty() ? "none" : text;
}

}  // namespace

std::string configComparisonMarkdown(const ConfigComparisonResult& result, const std::string& currentName,
                                     const std::string& savedName)
{
    std::string md = "| config | frames | failed | ball detected in | detection ratio (%) | false positives "
                     "| avg time (ms) |\n|---|---|---|---|---|---|---|\n";
    md += row(currentName, result.current, result.currentRow, result.hasTruth);
    if (result.hasSaved) md += row(savedName, result.saved, result.savedRow, result.hasTruth);
    md += "\n";
    if (!result.hasTruth) md += "No truth.csv: detection ratio and false positives need ground truth.\n";
    if (result.cancelled)
        md += "Cancelled after " + std::to_string(result.visited) + " frames: the numbers cover those only.\n";
    if (!result.firstFrameError.empty()) md += "First frame not processed: " + result.firstFrameError + "\n";
    if (!result.hasSaved) return md + result.savedNote + "\n";
    if (result.savedIsCurrent) return md + "Both configs detect the same: no frame changed.\n";
    const SessionComparison& c = result.comparison;
    md += "Changed frames: " + std::to_string(c.changed()) + " of " + std::to_string(c.frames.size()) + " (" +
          std::to_string(c.appeared) + " appeared, " + std::to_string(c.vanished) + " vanished, " +
          std::to_string(c.moved) + " moved; " + currentName + " against " + savedName + ")\n";
    md += "- appeared (only " + currentName + " finds a ball): " + frameList(c, FrameChange::Appeared) + "\n";
    md += "- vanished (only " + savedName + " finds a ball): " + frameList(c, FrameChange::Vanished) + "\n";
    md += "- moved (both find one, far apart): " + frameList(c, FrameChange::Moved) + "\n";
    return md;
}

}  // namespace omnitune
