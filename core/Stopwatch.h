#pragma once
// Stage timings on one monotonic clock: each lap() is the time since the previous one.
#include <chrono>

namespace omnitune {

class Stopwatch {
public:
    // Milliseconds since construction or the previous lap().
    double lap()
    {
        const auto now = Clock::now();
        const double ms = std::chrono::duration<double, std::milli>(now - last_).count();
        last_ = now;
        return ms;
    }
    // Milliseconds since construction.
    double total() const { return std::chrono::duration<double, std::milli>(Clock::now() - start_).count(); }

private:
    using Clock = std::chrono::steady_clock;
    Clock::time_point start_ = Clock::now();
    Clock::time_point last_ = start_;
};

}  // namespace omnitune
