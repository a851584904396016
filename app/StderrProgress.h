#pragma once
// Progress for the command-line tools: one line on stderr, rewritten every few percent, only
// when stderr is a terminal (logs and CI output stay clean).
#include "core/Progress.h"

#include <cstdio>
#include <string>
#include <unistd.h>

namespace omnitune {

class StderrProgress : public Progress {
public:
    explicit StderrProgress(std::string label) : label_(std::move(label)), tty_(::isatty(2) != 0) {}
    ~StderrProgress() override
    {
        if (tty_ && shown_ >= 0) std::fputc('\n', stderr);
    }
    void update(double percent) override
    {
        const int p = int(percent);
        if (!tty_ || p < shown_ + 5) return;
        shown_ = p;
        std::fprintf(stderr, "\r%s: %3d %%", label_.c_str(), p);
        std::fflush(stderr);
    }
    bool isCancelRequested() const override { return false; }

private:
    std::string label_;
    bool tty_;
    int shown_ = -5;
};

}  // namespace omnitune
