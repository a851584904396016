#include "calib/fit/CameraMeasurements.h"

#include "calib/fit/NumberCsv.h"

#include <opencv2/imgcodecs.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace omnitune {

namespace {

std::string number(double v)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.4f", v);
    return buf;
}

std::string readText(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

}  // namespace

std::optional<std::string> saveCameraMeasurements(const CameraMeasurements& m, const std::string& folder)
{
    std::error_code ec;
    fs::create_directories(folder, ec);
    if (ec) return "cannot create " + folder + ": " + ec.message();
    const fs::path dir(folder);
    {
        std::ofstream out(dir / "calibration_points.csv");
        out << "x,y,distance_m\n";
        for (const CalibrationPoint& p : m.points)
            out << number(p.fromImagePoint ? p.xPx : p.radiusPx) << "," << number(p.yPx) << "," << number(p.distanceM) << "\n";
        if (!out) return "cannot write " + (dir / "calibration_points.csv").string();
    }
    {
        std::ofstream out(dir / "ball_marks.csv");
        out << "x,y,radius_px,distance_m\n";
        for (const BallMark& b : m.balls)
            out << number(b.x) << "," << number(b.y) << "," << number(b.radiusPx) << "," << number(b.distanceM) << "\n";
        if (!out) return "cannot write " + (dir / "ball_marks.csv").string();
    }
    for (std::size_t i = 0; i < m.emptyFrames.size(); ++i) {
        char name[32];
        std::snprintf(name, sizeof name, "empty_%03zu.png", i);
        if (!cv::imwrite((dir / name).string(), m.emptyFrames[i])) return "cannot write " + (dir / name).string();
    }
    if (!m.mask.empty() && !cv::imwrite((dir / "mask.png").string(), m.mask)) return "cannot write mask.png";
    if (m.viewpointHeight > 0) {
        std::ofstream out(dir / "viewpoint_height.txt");
        out << number(m.viewpointHeight) << "\n";
    }
    return std::nullopt;
}

std::optional<CameraMeasurements> loadCameraMeasurements(const std::string& folder, std::string& error)
{
    const fs::path dir(folder);
    CameraMeasurements m;
    const CalibrationPointsParse points = loadCalibrationPoints((dir / "calibration_points.csv").string());
    if (!points.ok()) {
        error = points.error->toString();
        return std::nullopt;
    }
    m.points = points.points;
    const NumberCsv balls = parseNumberCsv(readText(dir / "ball_marks.csv"), "ball_marks.csv",
                                           {"x", "y", "radius_px", "distance_m"});
    if (!balls.has("x") || !balls.has("y") || !balls.has("radius_px") || !balls.has("distance_m")) {
        error = (dir / "ball_marks.csv").string() + ": needs the columns x,y,radius_px,distance_m";
        return std::nullopt;
    }
    for (const auto& row : balls.rows)
        m.balls.push_back({row.values.at("x"), row.values.at("y"), row.values.at("radius_px"), row.values.at("distance_m")});
    for (int i = 0;; ++i) {
        char name[32];
        std::snprintf(name, sizeof name, "empty_%03d.png", i);
        if (!fs::exists(dir / name)) break;
        m.emptyFrames.push_back(cv::imread((dir / name).string(), cv::IMREAD_COLOR));
    }
    if (m.emptyFrames.empty()) {
        error = folder + ": no empty_000.png";
        return std::nullopt;
    }
    if (fs::exists(dir / "mask.png")) m.mask = cv::imread((dir / "mask.png").string(), cv::IMREAD_GRAYSCALE);
    if (fs::exists(dir / "viewpoint_height.txt")) {
        std::istringstream in(readText(dir / "viewpoint_height.txt"));
        in >> m.viewpointHeight;
    }
    return m;
}

}  // namespace omnitune
