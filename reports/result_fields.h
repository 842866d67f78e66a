// Reading results.json (docs/results-format.md) without trusting it: a field
// that is missing, null or of another type reads as empty, never throws, so a
// report of a run that broke half way still shows what is there.
#pragma once

#include "comparison/run_status.h"
#include "comparison/verdict.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace reports {

using Json = nlohmann::ordered_json;

// Throws std::invalid_argument unless `results` is an object whose "format",
// when present, is "lightcts-results".
void checkResultsFormat(const Json& results);

// The array or object at `key`, or an empty one.
const Json& arrayField(const Json& object, std::string_view key);
const Json& objectField(const Json& object, std::string_view key);

// A string as it is; a number or boolean as JSON text; an array of those
// joined with ", "; anything else "".
std::string textField(const Json& object, std::string_view key);
std::optional<double> numberField(const Json& object, std::string_view key);

// For tables: a number with `digits` significant digits, a string as it is
// (results write "nan" and "inf" that way), null or missing as "-".
std::string formatValue(const Json& value, int digits = 4);
std::string formatField(const Json& object, std::string_view key, int digits = 4);
// The array field `key` (scene names: killers, killed_by) as "a, b, c"; "" when absent.
std::string joinedField(const Json& object, std::string_view key);
// A measured error (max_abs_error, rmse, tightness): null there means the
// value was not finite (results.json has no NaN or infinity), "non-finite".
std::string formatMetric(const Json& metrics, std::string_view key, int digits = 4);
std::string formatSeconds(double seconds);  // "12.345"

// A test's verdict, a mutant's or a backend's status, as results.json spells
// it, read through comparison/verdict.h and run_status.h (where each known
// word's meaning is defined). results.json is not trusted: a word those do
// not know counts against the run, because a report must never turn
// something it does not understand into a pass.
using Outcome = comparison::CiOutcome;
Outcome outcomeOf(std::string_view verdict);     // unknown: Failure
bool needsAttention(std::string_view verdict);   // a section with evidence in the HTML report; unknown: true
bool mutantFailed(std::string_view status);      // not killed, nor NotSupported; unknown: true
Outcome mutantOutcome(std::string_view status);  // unknown: Failure
bool backendFailed(std::string_view status);     // an error; unknown: true
Outcome backendOutcome(std::string_view status); // unknown: Error

// Backend suffixes: those of "backends" in order, then any that only tests or
// mutants name, in order of first appearance.
std::vector<std::string> backendOrder(const Json& results);

}  // namespace reports
