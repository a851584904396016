#include "calib/eval/FalsePositiveList.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <system_error>

namespace omnitune {

namespace {

// A file name part: letters and digits kept, everything else '-'.
std::string fileSafe(const std::string& s)
{
    std::string out = s;
    for (char& ch : out)
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '-';
    return out;
}

}  // namespace

std::string falsePositiveListMarkdown(const QualityRun& run, const std::vector<std::size_t>& variants)
{
    std::string md =
        "| variant | cell | frame | ball | at (x, y) | r exp | dist | search, place | non-green | non-black | "
        "circ | spread | run-on | fit r (dx, dy) |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    int rows = 0;
    for (std::size_t v : variants) {
        for (const QualityCellResult& cell : run.cells) {
            for (const FalsePositiveFrame& fp : cell.tallies[v].falsePositiveFrames) {
                const BallCandidate& c = fp.chosen;
                const ValidationScores& s = c.scores;
                char ball[64] = "none";
                if (fp.ballVisible) std::snprintf(ball, sizeof ball, "(%.0f, %.0f) r %.1f", fp.truthPx, fp.truthPy, fp.truthRadiusPx);
                char line[640];
                std::snprintf(line, sizeof line,
                              "| %s | %s | %d | %s | (%d, %d) | %.1f | %.0f | %s, %s | %.0f | %.0f | %.0f | %.2f | %.0f | "
                              "%.1f (%.1f, %.1f) |\n",
                              run.variants[v].name.c_str(), cell.name.c_str(), fp.frame, ball, c.x, c.y, c.expectedRadiusPx,
                              c.distancePx, std::string(candidateSourceName(fp.kind.source)).c_str(),
                              std::string(falsePositivePlaceName(fp.kind.place)).c_str(), s.nonGreenPct, s.nonBlackPct,
                              s.circularityPct, s.borderSpreadPx, s.runOnPct, s.fitRadiusPx, s.fitDx, s.fitDy);
                md += line;
                ++rows;
            }
        }
    }
    if (rows == 0) md += "| (none) | | | | | | | | | | | | | |\n";
    return md;
}

std::optional<std::string> writeFalsePositiveCrops(const QualityRun& run, const std::vector<std::size_t>& variants,
                                                   const std::string& folder, int scale)
{
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (ec) return folder + ": cannot be created (" + ec.message() + ")";
    for (std::size_t v : variants) {
        for (const QualityCellResult& cell : run.cells) {
            for (const FalsePositiveFrame& fp : cell.tallies[v].falsePositiveFrames) {
                if (fp.crop.empty()) continue;
                cv::Mat big;
                cv::resize(fp.crop, big, cv::Size(), scale, scale, cv::INTER_NEAREST);
                auto toBig = [&](double x, double y) {
                    return cv::Point(int((x - fp.cropOrigin.x + 0.5) * scale), int((y - fp.cropOrigin.y + 0.5) * scale));
                };
                const BallCandidate& c = fp.chosen;
                cv::circle(big, toBig(c.x, c.y), int(c.expectedRadiusPx * scale), cv::Scalar(0, 0, 255), 1, cv::LINE_AA);
                if (fp.ballVisible)
                    cv::circle(big, toBig(fp.truthPx, fp.truthPy), int(fp.truthRadiusPx * scale), cv::Scalar(0, 255, 0), 1,
                               cv::LINE_AA);
                const std::string path = (std::filesystem::path(folder) /
                                          (fileSafe(run.variants[v].name) + "_" + fileSafe(cell.name) + "_f" +
                                           std::to_string(fp.frame) + ".png"))
                                             .string();
                if (!cv::imwrite(path, big)) return path + ": cannot be written";
            }
        }
    }
    return std::nullopt;
}

}  // namespace omnitune
