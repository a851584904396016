#include "widgets/ConfigDrag.h"

#include "widgets/ConfigDocument.h"

namespace omnitune {

void ConfigDrag::begin()
{
    start_ = doc_->config();
    active_ = true;
    moved_ = false;
}

void ConfigDrag::show(const Config& next)
{
    if (!active_ || !checkConfig(next).empty()) return;
    moved_ = true;
    doc_->applyConfig(next);  // live, outside the undo stack
}

bool ConfigDrag::finish(const QString& what, std::optional<QString>* refused)
{
    if (!active_) return false;
    active_ = false;
    if (!moved_) return false;
    const Config next = doc_->config();  // the last valid position
    doc_->applyConfig(start_);           // the undo step goes from where the drag began
    const auto why = doc_->replaceConfig(next, what);
    if (refused) *refused = why;
    return !why;
}

void ConfigDrag::cancel()
{
    if (active_ && moved_) doc_->applyConfig(start_);
    active_ = false;
}

}  // namespace omnitune
