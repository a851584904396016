#pragma once
// A drag on the panes that edits the config (a region, a ray's end): shown live while the
// mouse moves, without an undo step per move; one undo step when the drag ends; back to where
// it began when it is cut short (Esc, the mode switched off mid-drag).
#include "core/Config.h"

#include <QString>

#include <optional>

namespace omnitune {

class ConfigDocument;

class ConfigDrag {
public:
    explicit ConfigDrag(ConfigDocument* doc) : doc_(doc) {}

    void begin();
    bool isActive() const { return active_; }
    // The config as the drag began.
    const Config& start() const { return start_; }
    // Shows `next` at once when checkConfig accepts it; an invalid one is skipped.
    void show(const Config& next);
    // Ends the drag as one undo step named `what` from the start to the last valid `show`n
    // config; false when nothing moved. `refused`: the document's reason when it refuses.
    bool finish(const QString& what, std::optional<QString>* refused = nullptr);
    // Ends the drag back where it began.
    void cancel();

private:
    ConfigDocument* doc_;
    Config start_;
    bool active_ = false;
    bool moved_ = false;
};

}  // namespace omnitune
