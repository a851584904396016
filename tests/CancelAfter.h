#pragma once
// A Progress for tests that asks to stop once `after` updates were seen.
#include "core/Progress.h"

namespace omnitune::testing {

class CancelAfter : public Progress {
public:
    explicit CancelAfter(int after) : after_(after) {}
    void update(double) override { ++seen_; }
    bool isCancelRequested() const override { return seen_ >= after_; }

private:
    int after_;
    int seen_ = 0;
};

}  // namespace omnitune::testing
