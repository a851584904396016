#pragma once
// One config key set to a value given as text ("validation.first_edge_only", "false"), and the
// table of the detector's deliberate deviations from the thesis as (key, thesis value) rows, so
// that each can be measured switched off (the quality gate's "deviations" runs, issue 9 sec. 5).
#include "core/Config.h"

#include <optional>
#include <string>
#include <vector>

namespace omnitune {

struct ConfigOverride {
    std::string key;    // schema path, e.g. "validation.max_run_on_pct"
    std::string value;  // as written in config.yml: "false", "100", "[70, 105]", "specific"
    std::string why;    // one line for reports (the deviations table's third column); may be empty
};

// Sets the key in `config`; on failure leaves `config` as it was and returns why (unknown key,
// a value that is not of the key's type or outside its range).
std::optional<std::string> applyConfigOverride(Config& config, const ConfigOverride& override);

// "key=value" as reports name a run.
std::string overrideLabel(const ConfigOverride& override);

// The deviations file (tests/quality_gate_deviations.csv): a header "key,thesis_value,why",
// then one row per deviation; '#' lines and blank lines are skipped; the why column may hold
// commas (everything after the second comma). `error` names the first bad line.
std::vector<ConfigOverride> parseDeviationsCsv(const std::string& text, std::string& error);

}  // namespace omnitune
