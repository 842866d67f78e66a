#include "results/results_file.h"

#include <fstream>

namespace results {
namespace {

// The keys every results.json has had, per record: what a reader cannot do without.
constexpr const char* kRunKeys[] = {"tests", "backends"};
constexpr const char* kTestKeys[] = {"name", "backend", "verdict"};
constexpr const char* kBackendKeys[] = {"backend", "status"};

template <std::size_t N>
void requireStrings(const Json& record, const std::string& path, const char* const (&keys)[N], const std::string& where) {
  for (const char* key : keys) {
    const auto it = record.find(key);
    if (it == record.end()) throw ResultsFileError(where + ": " + path + "." + key + " is missing");
    if (!it->is_string()) throw ResultsFileError(where + ": " + path + "." + key + " is not a string");
  }
}

template <std::size_t N>
void requireRecords(const Json& run, const char* arrayKey, const char* const (&keys)[N], const std::string& where) {
  const Json& array = run[arrayKey];
  for (std::size_t i = 0; i < array.size(); ++i) {
    const std::string path = std::string(arrayKey) + "[" + std::to_string(i) + "]";
    if (!array[i].is_object()) throw ResultsFileError(where + ": " + path + " is not an object");
    requireStrings(array[i], path, keys, where);
  }
}

// The checks on JSON read already; `where` starts each message.
RunRecord checkedRunRecord(const Json& json, const std::string& where) {
  if (!json.is_object() || json.value("format", Json()) != "lightcts-results")
    throw ResultsFileError(where + ": not a lightcts results.json (no \"format\": \"lightcts-results\")");
  for (const char* key : kRunKeys) {
    if (!json.contains(key)) throw ResultsFileError(where + ": " + key + " is missing");
    if (!json[key].is_array()) throw ResultsFileError(where + ": " + key + " is not an array");
  }
  requireRecords(json, "tests", kTestKeys, where);
  requireRecords(json, "backends", kBackendKeys, where);
  try {
    return RunRecord::fromJson(json);
  } catch (const std::invalid_argument& e) {
    throw ResultsFileError(where + ": " + e.what());
  }
}

}  // namespace

RunRecord readResultsFile(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw ResultsFileError(file.string() + ": cannot be read");
  Json json;
  try {
    json = Json::parse(in);
  } catch (const Json::parse_error& e) {
    throw ResultsFileError(file.string() + ": not JSON: " + e.what());
  }
  return checkedRunRecord(json, file.string());
}

}  // namespace results
