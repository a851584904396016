#pragma once
// The result of a two-config run as text for the command line (omnitune-eval --compare): a
// Markdown table with one row per config, then the frames that changed between them.
#include "calib/eval/ConfigComparisonRun.h"

#include <string>

namespace omnitune {

// `currentName` and `savedName` label the rows (usually the two file names).
std::string configComparisonMarkdown(const ConfigComparisonResult& result, const std::string& currentName,
                                     const std::string& savedName);

}  // namespace omnitune
