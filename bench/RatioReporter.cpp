#include "RatioReporter.h"

#include <cstdio>

void RatioReporter::ReportRuns(const std::vector<Run>& runs)
{
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs) {
        if (r.run_type != Run::RT_Iteration || r.iterations == 0) continue;
        // GetAdjustedRealTime() is in the run's unit; the multiplier is units per second.
        double ms = r.GetAdjustedRealTime() / benchmark::GetTimeUnitMultiplier(r.time_unit) * 1e3;
        // Benchmarks whose iteration is a pass over several frames say how many.
        const auto perIteration = r.counters.find("frames_per_iteration");
        if (perIteration != r.counters.end() && perIteration->second.value > 0) ms /= perIteration->second.value;
        times_.emplace_back(r.benchmark_name(), ms);
    }
}

void RatioReporter::Finalize()
{
    ConsoleReporter::Finalize();
    for (const auto& [prefix, reference] : groups_) {
        double referenceMs = 0;
        for (const auto& [name, ms] : times_)
            if (name.rfind(reference, 0) == 0) referenceMs = ms;
        bool header = false;
        for (const auto& [name, ms] : times_) {
            // The first group whose prefix the name starts with owns it.
            const std::string* owner = nullptr;
            for (const auto& g : groups_)
                if (!owner && name.rfind(g.first, 0) == 0) owner = &g.first;
            if (!owner || *owner != prefix) continue;
            if (!header) {
                std::printf("\nPer frame, as a ratio to %s (%.3f ms) in this run:\n", reference.c_str(), referenceMs);
                std::printf("%-44s %10s %10s\n", "benchmark", "ms/frame", "ratio");
                header = true;
            }
            std::printf("%-44s %10.3f %10.3f\n", name.c_str(), ms, referenceMs > 0 ? ms / referenceMs : 0.0);
        }
    }
}
