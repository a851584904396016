#pragma once
// A recorded session's errors and warnings (session.yml, truth.csv, frames/, the reader and
// the writer) are FileIssues, like the config's; the names say which files they are about.
#include "core/FileIssue.h"

namespace omnitune {

using SessionIssue = FileIssue;
using SessionIssueKind = FileIssueKind;

}  // namespace omnitune
