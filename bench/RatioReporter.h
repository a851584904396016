#pragma once
// A console reporter that ends the run with every benchmark's time as a ratio to a reference
// benchmark (cv::HoughCircles with the thesis' parameters on the same frames), measured in the
// same run. Families of benchmarks on different frames each name their own reference.
#include <benchmark/benchmark.h>

#include <map>
#include <string>
#include <vector>

class RatioReporter : public benchmark::ConsoleReporter {
public:
    explicit RatioReporter(std::string reference) : groups_{{"", std::move(reference)}} {}
    // (name prefix, reference benchmark): a benchmark is compared with the reference of the
    // first prefix its name starts with ("" matches every name).
    explicit RatioReporter(std::vector<std::pair<std::string, std::string>> groups) : groups_(std::move(groups)) {}
    void ReportRuns(const std::vector<Run>& runs) override;
    void Finalize() override;

private:
    std::vector<std::pair<std::string, std::string>> groups_;
    std::vector<std::pair<std::string, double>> times_;  // name, real ms per iteration, in run order
};
