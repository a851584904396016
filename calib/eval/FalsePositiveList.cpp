#include "calib/eval/FalsePositiveList.h"

#include "calib/eval/CandidateCells.h"
#include "calib/eval/FrameCrop.h"

#include <cstdio>
#include <filesystem>

namespace omnitune {

std::string falsePositiveListMarkdown(const QualityRun& run, const std::vector<std::size_t>& variants)
{
    std::string md = "| variant | cell | frame | ball | place |" + candidateCellsHeader() + "\n|---|---|---|---|---|" +
                     candidateCellsRule() + "\n";
    int rows = 0;
    for (std::size_t v : variants) {
        for (const QualityCellResult& cell : run.cells) {
            for (const FalsePositiveFrame& fp : cell.tallies[v].falsePositiveFrames) {
                char ball[64] = "none";
                if (fp.ballVisible) std::snprintf(ball, sizeof ball, "(%.0f, %.0f) r %.1f", fp.truthPx, fp.truthPy, fp.truthRadiusPx);
                md += "| " + run.variants[v].name + " | " + cell.name + " | " + std::to_string(fp.frame) + " | " + ball +
                      " | " + std::string(falsePositivePlaceName(fp.kind.place)) + " |" + candidateCells(fp.chosen) + "\n";
                ++rows;
            }
        }
    }
    if (rows == 0) md += "| (none) | | | | |" + emptyCandidateCells() + "\n";
    return md;
}

std::optional<std::string> writeFalsePositiveCrops(const QualityRun& run, const std::vector<std::size_t>& variants,
                                                   const std::string& folder, int scale)
{
    if (auto e = makeCropFolder(folder)) return e;
    for (std::size_t v : variants) {
        for (const QualityCellResult& cell : run.cells) {
            for (const FalsePositiveFrame& fp : cell.tallies[v].falsePositiveFrames) {
                const BallCandidate& c = fp.chosen;
                std::vector<CropCircle> circles{{double(c.x), double(c.y), c.expectedRadiusPx, cv::Scalar(0, 0, 255)}};
                if (fp.ballVisible) circles.push_back({fp.truthPx, fp.truthPy, fp.truthRadiusPx, cv::Scalar(0, 255, 0)});
                const std::string path = (std::filesystem::path(folder) /
                                          (fileSafe(run.variants[v].name) + "_" + fileSafe(cell.name) + "_f" +
                                           std::to_string(fp.frame) + ".png"))
                                             .string();
                if (auto e = writeEnlargedCrop(path, fp.crop, scale, circles)) return e;
            }
        }
    }
    return std::nullopt;
}

}  // namespace omnitune
