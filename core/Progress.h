#pragma once
// Progress and cancellation for long work (a session re-run, a fit, a recording). The GUI
// implements it with a progress dialog, the command-line tools with a line on stderr.

namespace omnitune {

class Progress {
public:
    virtual ~Progress() = default;
    virtual void update(double percent) = 0;
    virtual bool isCancelRequested() const = 0;
};

}  // namespace omnitune
