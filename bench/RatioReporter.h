#pragma once
// A console reporter that ends the run with every benchmark's time as a ratio to one
// reference benchmark (cv::HoughCircles with the thesis' parameters), measured in the same run.
#include <benchmark/benchmark.h>

#include <map>
#include <string>
#include <vector>

class RatioReporter : public benchmark::ConsoleReporter {
public:
    explicit RatioReporter(std::string reference) : reference_(std::move(reference)) {}
    void ReportRuns(const std::vector<Run>& runs) override;
    void Finalize() override;

private:
    std::string reference_;
    std::vector<std::pair<std::string, double>> times_;  // name, real ms per iteration, in run order
};
