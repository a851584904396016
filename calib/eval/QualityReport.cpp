#include "calib/eval/QualityReport.h"

#include <algorithm>
#include <cstdio>
#include <functional>

namespace omnitune {

namespace {

std::string format(const char* f, double v)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, f, v);
    return buf;
}

std::string pct(const BallFrameTally& t)
{
    if (t.withBall == 0) return "—";
    return format("%.1f %%", t.detectionPct()) + " (" + std::to_string(t.correct) + "/" + std::to_string(t.withBall) + ")";
}

std::string fp(const QualityTally& t)
{
    return format("%.2f %%", t.falsePositivePct()) + " (" + std::to_string(t.falsePositives) + "/" +
           std::to_string(t.frames) + ")";
}

std::string range(const QualityTally& t)
{
    if (t.rangeErrorsM.size() < 2) return "—";
    char buf[96];
    std::snprintf(buf, sizeof buf, "%+.1f / %.1f cm (%zu)", t.rangeBiasCm(), t.rangeStdCm(), t.rangeErrorsM.size());
    return buf;
}

bool ball(const OpticsCell& c) { return c.ballPresent; }

}  // namespace

std::vector<std::size_t> shippedVariants(const QualityRun& run)
{
    std::vector<std::size_t> v;
    for (std::size_t i = 0; i < run.variants.size(); ++i)
        if (run.variants[i].overrides.empty()) v.push_back(i);
    return v;
}

std::string qualitySummaryMarkdown(const QualityRun& run, const std::vector<std::size_t>& variants)
{
    std::string md =
        "| algorithm | balls found | worst cell | false-positive frames | range error ≤ 4 m (bias / std, n) "
        "| time p50 / p99 (ms) |\n|---|---|---|---|---|---|\n";
    for (std::size_t v : variants) {
        const QualityTally balls = qualityTotal(run, v, ball);
        const QualityTally all = qualityTotal(run, v);
        const QualityCellResult* worst = worstQualityCell(run, v);
        const std::string worstText =
            worst ? format("%.0f %%", worst->tallies[v].detectionPct()) + " `" + worst->name + "`" : "—";
        char time[64];
        std::snprintf(time, sizeof time, "%.1f / %.1f", all.timePercentileMs(50), all.timePercentileMs(99));
        md += "| " + run.variants[v].name + " | " + pct(balls) + " | " + worstText + " | " + fp(all) + " | " +
              range(balls) + " | " + time + " |\n";
    }
    return md;
}

namespace {

// A row of the by-condition tables: a label and the ball cells it sums.
struct ConditionRow {
    std::string label;
    std::function<bool(const OpticsCell&)> filter;
};

// "ball: orange", "light: dim", ... : the distinct values of each property in matrix order.
std::vector<ConditionRow> conditionRows(const QualityRun& run)
{
    std::vector<ConditionRow> out;
    auto rows = [&](const std::string& label, std::string (*property)(const OpticsCell&)) {
        std::vector<std::string> seen;
        for (const QualityCellResult& c : run.cells) {
            if (!c.cell.ballPresent) continue;
            const std::string value = property(c.cell);
            if (std::find(seen.begin(), seen.end(), value) != seen.end()) continue;
            seen.push_back(value);
            out.push_back({label + ": " + value,
                           [property, value](const OpticsCell& x) { return x.ballPresent && property(x) == value; }});
        }
    };
    rows("ball", [](const OpticsCell& c) { return std::string(ballKindName(c.ball)); });
    rows("light", [](const OpticsCell& c) { return opticsLightName(c.light); });
    rows("distractors", [](const OpticsCell& c) { return opticsDistractorsName(c.distractors); });
    rows("carpet", [](const OpticsCell& c) { return opticsCarpetName(c.carpet); });
    rows("frame", [](const OpticsCell& c) {
        return std::to_string(c.image.width) + "x" + std::to_string(c.image.height) + " " + opticsMirrorName(c.mirror);
    });
    return out;
}

// A table's header: `first`, then one column per variant.
std::string variantColumnsHeader(const QualityRun& run, const std::vector<std::size_t>& variants, const std::string& first)
{
    std::string md = "| " + first + " |";
    std::string rule = "|---|";
    for (std::size_t v : variants) {
        md += " " + run.variants[v].name + " |";
        rule += "---|";
    }
    return md + "\n" + rule + "\n";
}

}  // namespace

std::string qualityBreakdownMarkdown(const QualityRun& run, const std::vector<std::size_t>& variants)
{
    std::string md = variantColumnsHeader(run, variants, "condition");
    for (const ConditionRow& row : conditionRows(run)) {
        md += "| " + row.label + " |";
        for (std::size_t v : variants) md += " " + pct(qualityTotal(run, v, row.filter)) + " |";
        md += "\n";
    }
    std::vector<QualityTally> totals;
    for (std::size_t v : variants) totals.push_back(qualityTotal(run, v));
    for (std::size_t p = 0; p < kBallPlaceCount; ++p) {
        if (totals.empty() || totals.front().byPlace[p].withBall == 0) continue;
        md += "| " + std::string(ballPlaceName(BallPlace(p))) + " |";
        for (const QualityTally& t : totals) md += " " + pct(t.byPlace[p]) + " |";
        md += "\n";
    }
    return md;
}

std::string qualityMissesMarkdown(const QualityRun& run, std::size_t variant)
{
    std::string md = "| condition | missed |";
    std::string rule = "|---|---|";
    for (std::size_t i = 0; i < kMissCauseCount; ++i) {
        md += " " + std::string(missCauseName(MissCause(i))) + " |";
        rule += "---|";
    }
    md += " radius model off | by the prefilter |\n" + rule + "---|---|\n";
    auto row = [&](const std::string& label, const BallFrameTally& t) {
        md += "| " + label + " | " + std::to_string(t.withBall - t.correct) + " |";
        for (int n : t.missCauses) md += " " + (n ? std::to_string(n) : std::string("·")) + " |";
        md += " " + std::to_string(t.missesRadiusOff) + " | " + std::to_string(t.missesPrefiltered) + " |\n";
    };
    const QualityTally all = qualityTotal(run, variant, ball);
    row("all ball cells", all);
    for (const ConditionRow& r : conditionRows(run)) row(r.label, qualityTotal(run, variant, r.filter));
    for (std::size_t p = 0; p < kBallPlaceCount; ++p)
        if (all.byPlace[p].withBall > 0) row(ballPlaceName(BallPlace(p)), all.byPlace[p]);
    return md;
}

std::string qualityFalsePositivesMarkdown(const QualityRun& run, const std::vector<std::size_t>& variants)
{
    std::string md = variantColumnsHeader(run, variants, "what it hit (search, place)");
    std::vector<QualityTally> totals;
    std::vector<QualityTally> ballFree;
    for (std::size_t v : variants) {
        totals.push_back(qualityTotal(run, v));
        ballFree.push_back(qualityTotal(run, v, [](const OpticsCell& c) { return !c.ballPresent; }));
    }
    for (std::size_t k = 0; k < kFalsePositiveKindCount; ++k) {
        bool any = false;
        for (const QualityTally& t : totals) any = any || t.falsePositiveKinds[k] > 0;
        if (!any) continue;
        const FalsePositiveKind kind = falsePositiveKindAt(k);
        md += "| " + std::string(candidateSourceName(kind.source)) + ", " +
              std::string(falsePositivePlaceName(kind.place)) + " |";
        for (std::size_t i = 0; i < totals.size(); ++i)
            md += " " + std::to_string(totals[i].falsePositiveKinds[k]) + " (" +
                  std::to_string(ballFree[i].falsePositiveKinds[k]) + " ball-free) |";
        md += "\n";
    }
    md += "| all |";
    for (std::size_t i = 0; i < totals.size(); ++i)
        md += " " + std::to_string(totals[i].falsePositives) + " (" + std::to_string(ballFree[i].falsePositives) +
              " ball-free) |";
    md += "\n| not counted: a ball more than half hidden, found where it lies |";
    for (const QualityTally& t : totals) md += " " + std::to_string(t.atHiddenBalls) + " |";
    return md + "\n";
}

std::string qualityDeviationsMarkdown(const QualityRun& run)
{
    std::string md =
        "| run | balls found | Δ balls found | false-positive frames | Δ false positives | range std ≤ 4 m |\n"
        "|---|---|---|---|---|---|\n";
    for (std::size_t v = 0; v < run.variants.size(); ++v) {
        if (run.variants[v].overrides.empty()) continue;
        std::size_t shipped = run.variants.size();
        for (std::size_t s : shippedVariants(run))
            if (run.variants[s].algorithm == run.variants[v].algorithm) shipped = s;
        const QualityTally balls = qualityTotal(run, v, ball);
        const QualityTally all = qualityTotal(run, v);
        std::string dBalls = "—";
        std::string dFp = "—";
        if (shipped < run.variants.size()) {
            dBalls = format("%+.1f", balls.detectionPct() - qualityTotal(run, shipped, ball).detectionPct());
            dFp = format("%+.2f", all.falsePositivePct() - qualityTotal(run, shipped).falsePositivePct());
        }
        const std::string stdText = balls.rangeErrorsM.size() < 2 ? "—" : format("%.1f cm", balls.rangeStdCm());
        md += "| " + run.variants[v].name + " | " + pct(balls) + " | " + dBalls + " | " + fp(all) + " | " + dFp + " | " +
              stdText + " |\n";
    }
    return md;
}

std::string qualityWorstCellsMarkdown(const QualityRun& run, std::size_t variant, int count)
{
    std::vector<const QualityCellResult*> cells;
    for (const QualityCellResult& c : run.cells)
        if (variant < c.tallies.size() && c.tallies[variant].withBall > 0) cells.push_back(&c);
    std::stable_sort(cells.begin(), cells.end(), [&](const QualityCellResult* a, const QualityCellResult* b) {
        return a->tallies[variant].detectionPct() < b->tallies[variant].detectionPct();
    });
    std::string md = "| cell | balls found | false positives |\n|---|---|---|\n";
    for (int i = 0; i < count && i < int(cells.size()); ++i)
        md += "| `" + cells[i]->name + "` | " + pct(cells[i]->tallies[variant]) + " | " +
              std::to_string(cells[i]->tallies[variant].falsePositives) + " |\n";
    return md;
}

}  // namespace omnitune
