#include "RatioReporter.h"

#include <cstdio>

void RatioReporter::ReportRuns(const std::vector<Run>& runs)
{
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs) {
        if (r.run_type != Run::RT_Iteration || r.iterations == 0) continue;
        // GetAdjustedRealTime() is in the run's unit; the multiplier is units per second.
        const double ms = r.GetAdjustedRealTime() / benchmark::GetTimeUnitMultiplier(r.time_unit) * 1e3;
        times_.emplace_back(r.benchmark_name(), ms);
    }
}

void RatioReporter::Finalize()
{
    ConsoleReporter::Finalize();
    double reference = 0;
    for (const auto& [name, ms] : times_)
        if (name.rfind(reference_, 0) == 0) reference = ms;
    std::printf("\nPer frame, as a ratio to %s (%.3f ms) in this run:\n", reference_.c_str(), reference);
    std::printf("%-44s %10s %10s\n", "benchmark", "ms/frame", "ratio");
    for (const auto& [name, ms] : times_)
        std::printf("%-44s %10.3f %10.3f\n", name.c_str(), ms, reference > 0 ? ms / reference : 0.0);
}
