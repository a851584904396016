#pragma once
// The config's errors and warnings are FileIssues; the names say which file they are about.
#include "core/FileIssue.h"

namespace omnitune {

using ConfigIssue = FileIssue;
using ConfigIssueKind = FileIssueKind;

}  // namespace omnitune
