// How results/ reads a record's fields from JSON it did not write itself (a
// file a person hands it, an older lightcts's): a key that is missing or of
// another type reads as its default, so a record of a run that broke half way
// still reads. Internal to results/: everything else reads the records.
#pragma once

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace results::fields {

using Json = nlohmann::ordered_json;

inline std::string text(const Json& json, const char* key) {
  const auto it = json.find(key);
  return it != json.end() && it->is_string() ? it->get<std::string>() : std::string();
}

inline double number(const Json& json, const char* key) {
  const auto it = json.find(key);
  return it != json.end() && it->is_number() ? it->get<double>() : 0.0;
}

inline long long integer(const Json& json, const char* key) {
  const auto it = json.find(key);
  return it != json.end() && it->is_number() ? it->get<long long>() : 0;
}

inline bool boolean(const Json& json, const char* key) {
  const auto it = json.find(key);
  return it != json.end() && it->is_boolean() && it->get<bool>();
}

// A number that results.json writes as null where it is not finite (JSON has
// no NaN or infinity): nullopt for null, and for a missing key.
inline std::optional<double> measured(const Json& value) {
  return value.is_number() ? std::optional<double>(value.get<double>()) : std::nullopt;
}
inline std::optional<double> measured(const Json& json, const char* key) {
  const auto it = json.find(key);
  return it != json.end() ? measured(*it) : std::nullopt;
}
inline Json measuredJson(const std::optional<double>& value) { return value ? Json(*value) : Json(nullptr); }

inline Json carried(const Json& json, const char* key, Json absent = nullptr) {
  const auto it = json.find(key);
  return it != json.end() ? *it : absent;
}

inline std::vector<std::string> texts(const Json& json, const char* key) {
  std::vector<std::string> items;
  const auto it = json.find(key);
  if (it == json.end() || !it->is_array()) return items;
  for (const Json& item : *it)
    if (item.is_string()) items.push_back(item.get<std::string>());
  return items;
}

// Records as a JSON array, each by its toJson.
template <typename Record>
Json arrayOf(const std::vector<Record>& records) {
  Json array = Json::array();
  for (const Record& record : records) array.push_back(record.toJson());
  return array;
}

// The objects of the array at `key`, each read by `read`; what is no object is passed over.
template <typename Record, typename Read>
std::vector<Record> objects(const Json& json, const char* key, Read read) {
  std::vector<Record> records;
  const auto it = json.find(key);
  if (it == json.end() || !it->is_array()) return records;
  for (const Json& item : *it)
    if (item.is_object()) records.push_back(read(item));
  return records;
}

}  // namespace results::fields
