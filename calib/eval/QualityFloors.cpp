#include "calib/eval/QualityFloors.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace omnitune {

namespace {

struct MetricSpec {
    const char* name;
    bool atLeast;
    double targetSpecific;  // specific and combined
    double targetOpenCv;    // NaN: no target
};

const double kNone = std::nan("");
// issue 9, section 5.
const MetricSpec kMetrics[] = {
    {"detection_pct", true, 97.0, 70.0},
    {"cell_min_detection_pct", true, 85.0, kNone},
    {"false_positive_pct", false, 0.5, 0.5},
    {"range_std_cm", false, 5.0, 5.0},
};

std::string trimmed(const std::string& s)
{
    const auto b = s.find_first_not_of(" \t\r");
    if (b == std::string::npos) return {};
    return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

std::vector<std::string> fields(const std::string& line)
{
    std::vector<std::string> out;
    std::stringstream in(line);
    std::string f;
    while (std::getline(in, f, ',')) out.push_back(trimmed(f));
    if (!line.empty() && line.back() == ',') out.emplace_back();
    return out;
}

// "-" or empty: none.
bool optionalNumber(const std::string& text, std::optional<double>& out)
{
    if (text.empty() || text == "-") {
        out.reset();
        return true;
    }
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (end != text.c_str() + text.size() || !std::isfinite(v)) return false;
    out = v;
    return true;
}

std::string formatNumber(const std::optional<double>& v)
{
    if (!v) return "-";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", *v);
    return buf;
}

}  // namespace

std::optional<QualityFloorsFile> parseQualityFloors(const std::string& text, std::string& error)
{
    QualityFloorsFile file;
    std::stringstream in(text);
    std::string line;
    int number = 0;
    bool header = false;
    auto bad = [&](const std::string& why) {
        error = "line " + std::to_string(number) + ": " + why;
        return std::nullopt;
    };
    while (std::getline(in, line)) {
        ++number;
        const std::string t = trimmed(line);
        if (t.empty() || t[0] == '#') continue;
        const std::vector<std::string> f = fields(t);
        if (!header) {
            if (f.size() == 2 && f[0] == "pixel_format") {
                if (f[1] == pixelFormatName(PixelFormat::Bgr8)) file.pixelFormat = PixelFormat::Bgr8;
                else if (f[1] == pixelFormatName(PixelFormat::Uyvy)) file.pixelFormat = PixelFormat::Uyvy;
                else return bad("pixel_format must be bgr8 or uyvy, not '" + f[1] + "'");
                continue;
            }
            if (f.size() == 2) {
                char* end = nullptr;
                const long v = std::strtol(f[1].c_str(), &end, 10);
                if (end != f[1].c_str() + f[1].size() || v < 1 || v > 1000000) return bad("'" + f[1] + "' is not a positive whole number");
                if (f[0] == "frames_per_cell") file.matrix.framesPerCell = int(v);
                else if (f[0] == "ball_free_frames_per_cell") file.matrix.ballFreeFramesPerCell = int(v);
                else if (f[0] == "seed") file.matrix.seed = unsigned(v);
                else return bad("unknown setting '" + f[0] + "'");
                continue;
            }
            if (t.rfind("algorithm,metric,bound,target,floor", 0) != 0)
                return bad("expected the header 'algorithm,metric,bound,target,floor,measured'");
            header = true;
            continue;
        }
        if (f.size() < 5) return bad("expected 'algorithm,metric,bound,target,floor[,measured]'");
        QualityFloor q;
        q.algorithm = f[0];
        q.metric = f[1];
        if (std::none_of(std::begin(kMetrics), std::end(kMetrics), [&](const MetricSpec& m) { return q.metric == m.name; }))
            return bad("unknown metric '" + q.metric + "'");
        if (f[2] != "min" && f[2] != "max") return bad("bound must be min or max, not '" + f[2] + "'");
        q.atLeast = f[2] == "min";
        if (!optionalNumber(f[3], q.target) || !optionalNumber(f[4], q.floor) ||
            (f.size() > 5 && !optionalNumber(f[5], q.measured)))
            return bad("target, floor and measured are numbers or '-'");
        file.floors.push_back(q);
    }
    if (!header) {
        error = "no header 'algorithm,metric,bound,target,floor,measured'";
        return std::nullopt;
    }
    return file;
}

std::string serializeQualityFloors(const QualityFloorsFile& file)
{
    const bool uyvy = file.pixelFormat == PixelFormat::Uyvy;
    std::string s =
        "# Floors of the quality gate (tests/calib_quality_gate_test.cpp) on the optics simulator's matrix\n"
        "# (calib/eval/QualityMatrix.h). floor: what the test asserts (measured when written, less a margin);\n"
        "# target: issue 9's goal; '-': none. pixel_format: the frames as the detector read them.\n"
        "# Regenerate (after a detector change, on purpose):\n"
        "#   build/app/omnitune-eval --quality-matrix --threads 0 ";
    s += uyvy ? "--pixel-format uyvy --write-floors tests/quality_gate_floors_uyvy.csv\n"
              : "--write-floors tests/quality_gate_floors.csv\n";
    s += "pixel_format," + std::string(pixelFormatName(file.pixelFormat)) + "\n";
    s += "frames_per_cell," + std::to_string(file.matrix.framesPerCell) + "\n";
    s += "ball_free_frames_per_cell," + std::to_string(file.matrix.ballFreeFramesPerCell) + "\n";
    s += "seed," + std::to_string(file.matrix.seed) + "\n";
    s += "algorithm,metric,bound,target,floor,measured\n";
    for (const QualityFloor& q : file.floors)
        s += q.algorithm + "," + q.metric + "," + (q.atLeast ? "min" : "max") + "," + formatNumber(q.target) + "," +
             formatNumber(q.floor) + "," + formatNumber(q.measured) + "\n";
    return s;
}

std::optional<double> qualityMetric(const QualityRun& run, std::size_t variant, const std::string& metric)
{
    if (variant >= run.variants.size()) return std::nullopt;
    auto isBall = [](const OpticsCell& c) { return c.ballPresent; };
    if (metric == "detection_pct") {
        const QualityTally t = qualityTotal(run, variant, isBall);
        if (t.withBall == 0) return std::nullopt;
        return t.detectionPct();
    }
    if (metric == "cell_min_detection_pct") {
        const QualityCellResult* worst = worstQualityCell(run, variant);
        if (!worst) return std::nullopt;
        return worst->tallies[variant].detectionPct();
    }
    if (metric == "false_positive_pct") {
        const QualityTally t = qualityTotal(run, variant);
        if (t.frames == 0) return std::nullopt;
        return t.falsePositivePct();
    }
    if (metric == "range_std_cm") {
        const QualityTally t = qualityTotal(run, variant);
        if (t.rangeErrorsM.size() < 2) return std::nullopt;
        return t.rangeStdCm();
    }
    return std::nullopt;
}

QualityFloorsFile floorsFromRun(const QualityRun& run, const QualityMatrixOptions& matrix, PixelFormat pixelFormat)
{
    QualityFloorsFile file;
    file.matrix = matrix;
    file.pixelFormat = pixelFormat;
    for (std::size_t v = 0; v < run.variants.size(); ++v) {
        if (!run.variants[v].overrides.empty()) continue;
        const bool opencv = run.variants[v].algorithm == Algorithm::OpenCv;
        for (const MetricSpec& m : kMetrics) {
            QualityFloor q;
            q.algorithm = run.variants[v].name;
            q.metric = m.name;
            q.atLeast = m.atLeast;
            const double target = opencv ? m.targetOpenCv : m.targetSpecific;
            if (!std::isnan(target)) q.target = target;
            q.measured = qualityMetric(run, v, m.name);
            if (q.measured) {
                const double x = *q.measured;
                const std::string name = m.name;
                if (name == "detection_pct") q.floor = std::max(0.0, x - 2.0);
                else if (name == "cell_min_detection_pct") q.floor = std::max(0.0, x - 100.0 / std::max(1, matrix.framesPerCell));
                else if (name == "false_positive_pct") q.floor = std::min(100.0, x + 0.3);
                else q.floor = x + std::max(1.0, 0.2 * x);
                // Round away from the measurement so that the written two decimals still hold.
                *q.floor = q.atLeast ? std::floor(*q.floor * 100.0) / 100.0 : std::ceil(*q.floor * 100.0) / 100.0;
            }
            file.floors.push_back(q);
        }
    }
    return file;
}

std::vector<QualityFloorCheck> checkQualityFloors(const QualityRun& run, const QualityFloorsFile& file)
{
    std::vector<QualityFloorCheck> checks;
    char buf[256];
    for (const QualityFloor& q : file.floors) {
        std::size_t v = run.variants.size();
        for (std::size_t i = 0; i < run.variants.size(); ++i)
            if (run.variants[i].name == q.algorithm && run.variants[i].overrides.empty()) v = i;
        if (v == run.variants.size()) continue;
        QualityFloorCheck c;
        c.floor = q;
        c.measured = qualityMetric(run, v, q.metric);
        const char* cmp = q.atLeast ? ">=" : "<=";
        if (!q.floor) {
            std::snprintf(buf, sizeof buf, "%s %s %s: no floor", q.algorithm.c_str(), q.metric.c_str(),
                          formatNumber(c.measured).c_str());
        } else if (!c.measured) {
            c.passed = false;  // a floor that cannot be measured any more is a regression too
            std::snprintf(buf, sizeof buf, "%s %s not measurable (floor %s %.2f)", q.algorithm.c_str(), q.metric.c_str(),
                          cmp, *q.floor);
        } else {
            c.passed = q.atLeast ? *c.measured >= *q.floor : *c.measured <= *q.floor;
            std::snprintf(buf, sizeof buf, "%s %s %.2f %s floor %.2f: %s", q.algorithm.c_str(), q.metric.c_str(),
                          *c.measured, cmp, *q.floor, c.passed ? "ok" : "FELL");
        }
        c.line = buf;
        if (q.target && c.measured) {
            const double gap = q.atLeast ? *q.target - *c.measured : *c.measured - *q.target;
            std::snprintf(buf, sizeof buf, " (target %.2f: %s)", *q.target,
                          gap > 0 ? (formatNumber(gap) + " to go").c_str() : "reached");
            c.line += buf;
        }
        checks.push_back(c);
    }
    return checks;
}

}  // namespace omnitune
