#pragma once
// The workbench keeps each file as it was before this run of the program changed it: the
// first save of a path writes FILE.bak, later saves (and reopening the file) leave that .bak
// alone, so saving twice never turns the backup into a copy of the first save.
#include <QString>

namespace omnitune {

// True when a save in this run already kept `path`.bak.
bool backedUpThisRun(const QString& path);
// After a successful save that kept (or had no previous file to keep) the backup.
void rememberBackup(const QString& path);

}  // namespace omnitune
