// Reading a JSON file lightcts does not trust (a bench.json, Google
// Benchmark's output): a field that is missing, null or of another type reads
// as empty, never throws, so a page of a run that broke half way still shows
// what is there. results.json is read by results/ into records instead.
#pragma once

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <string_view>

namespace reports {

using Json = nlohmann::ordered_json;

// The array or object at `key`, or an empty one.
const Json& arrayField(const Json& object, std::string_view key);
const Json& objectField(const Json& object, std::string_view key);

// A string as it is; a number or boolean as JSON text; an array of those
// joined with ", "; anything else "".
std::string textField(const Json& object, std::string_view key);
std::optional<double> numberField(const Json& object, std::string_view key);

}  // namespace reports
