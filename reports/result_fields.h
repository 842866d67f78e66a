// What the reports of a run (the HTML page, junit.xml, the CSVs, `run
// compare`) share in reading its records (results/run_records.h): how a
// number is shown, and in which order the backends come.
#pragma once

#include "results/run_records.h"

#include <optional>
#include <string>
#include <vector>

namespace reports {

using Json = nlohmann::ordered_json;
using Outcome = comparison::CiOutcome;

// For tables: `digits` significant digits ("%.*g").
std::string formatNumber(double value, int digits = 4);
// A measured error (max_abs_error, rmse, tightness): none means the value
// was not finite (results.json has no NaN or infinity), "non-finite".
std::string formatMeasured(const results::Measured& value, int digits = 4);
// A value that may be absent: "-" when it is.
std::string formatOptional(const std::optional<double>& value, int digits = 4);
std::string formatSeconds(double seconds);  // "12.345"
// Items joined with ", " (killers, killed_by).
std::string joined(const std::vector<std::string>& items);

// Backend suffixes: those of the run's backends in order, then any that only
// tests or mutants name, in order of first appearance.
std::vector<std::string> backendOrder(const results::RunRecord& run);

}  // namespace reports
