#pragma once
// Offers back the unsaved edits an earlier run left for the document's config (RecoveryFile):
// a message box lists each key as "saved → recovered". Restore applies them as one undo step
// and leaves the document unsaved; Discard removes the file; Not now keeps it for the next
// time the config is opened.
#include <QStringList>

class QWidget;

namespace omnitune {

class ConfigDocument;
class RecoveryFile;

// Returns lines for the window's notices (what was restored or refused, an unreadable
// recovery file); empty when there was nothing to offer or the user declined.
QStringList offerRecovery(QWidget* parent, RecoveryFile& recovery, const ConfigDocument& doc);

}  // namespace omnitune
