#include "calib/eval/MissList.h"

#include "calib/eval/CandidateCells.h"
#include "calib/eval/FrameCrop.h"

#include <cstdio>
#include <filesystem>

namespace omnitune {

namespace {

bool wanted(const MissedFrame& m, std::optional<MissCause> cause) { return !cause || m.cause == *cause; }

}  // namespace

std::optional<MissCause> missCauseNamed(const std::string& name)
{
    for (std::size_t i = 0; i < kMissCauseCount; ++i) {
        const auto cause = MissCause(i);
        const std::string text(missCauseName(cause));
        if (name == text || name == fileSafe(text)) return cause;
    }
    return std::nullopt;
}

std::string missListMarkdown(const QualityRun& run, const std::vector<std::size_t>& variants, std::optional<MissCause> cause)
{
    std::string md = "| variant | cell | frame | ball (x, y) r, range | cause | candidate at the ball:" + candidateCellsHeader() +
                     " detected instead |\n|---|---|---|---|---|" + candidateCellsRule() + "---|\n";
    int rows = 0;
    for (std::size_t v : variants) {
        for (const QualityCellResult& cell : run.cells) {
            for (const MissedFrame& m : cell.tallies[v].missedFrames) {
                if (!wanted(m, cause)) continue;
                char ball[96];
                std::snprintf(ball, sizeof ball, "(%.0f, %.0f) r %.1f, %.2f m", m.truthPx, m.truthPy, m.truthRadiusPx,
                              m.truthRangeM);
                std::string why(missCauseName(m.cause));
                if (m.hasCandidate && m.atBallPrefiltered) why += " (prefilter)";
                if (m.radiusOff) why += " (radius model off)";
                char elsewhere[64] = "-";
                if (m.detected) std::snprintf(elsewhere, sizeof elsewhere, "(%d, %d)", m.chosen.x, m.chosen.y);
                md += "| " + run.variants[v].name + " | " + cell.name + " | " + std::to_string(m.frame) + " | " + ball + " | " +
                      why + " |" + (m.hasCandidate ? candidateCells(m.atBall) : emptyCandidateCells()) + " " + elsewhere +
                      " |\n";
                ++rows;
            }
        }
    }
    if (rows == 0) md += "| (none) | | | | |" + emptyCandidateCells() + " |\n";
    return md;
}

std::optional<std::string> writeMissCrops(const QualityRun& run, const std::vector<std::size_t>& variants,
                                          const std::string& folder, std::optional<MissCause> cause, int scale)
{
    if (auto e = makeCropFolder(folder)) return e;
    for (std::size_t v : variants) {
        for (const QualityCellResult& cell : run.cells) {
            for (const MissedFrame& m : cell.tallies[v].missedFrames) {
                if (!wanted(m, cause)) continue;
                std::vector<CropCircle> circles{{m.truthPx, m.truthPy, m.truthRadiusPx, cv::Scalar(0, 255, 0)}};
                if (m.hasCandidate)
                    circles.push_back({double(m.atBall.x), double(m.atBall.y), m.atBall.expectedRadiusPx, cv::Scalar(0, 0, 255)});
                if (m.detected)
                    circles.push_back({double(m.chosen.x), double(m.chosen.y), m.chosen.expectedRadiusPx, cv::Scalar(255, 0, 0)});
                const std::string name = fileSafe(run.variants[v].name) + "_" + fileSafe(cell.name) + "_f" +
                                         std::to_string(m.frame) + "_" + fileSafe(std::string(missCauseName(m.cause))) + ".png";
                if (auto e = writeEnlargedCrop((std::filesystem::path(folder) / name).string(), m.crop, scale, circles)) return e;
            }
        }
    }
    return std::nullopt;
}

}  // namespace omnitune
