#include "reports/result_fields.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace reports {

void checkResultsFormat(const Json& results) {
  if (!results.is_object()) throw std::invalid_argument("results.json: not a JSON object");
  const auto format = results.find("format");
  if (format != results.end() && *format != "lightcts-results")
    throw std::invalid_argument("results.json: format is " + format->dump() + ", not \"lightcts-results\"");
}

const Json& arrayField(const Json& object, std::string_view key) {
  static const Json empty = Json::array();
  if (!object.is_object()) return empty;
  const auto it = object.find(key);
  return it != object.end() && it->is_array() ? *it : empty;
}

const Json& objectField(const Json& object, std::string_view key) {
  static const Json empty = Json::object();
  if (!object.is_object()) return empty;
  const auto it = object.find(key);
  return it != object.end() && it->is_object() ? *it : empty;
}

std::string textField(const Json& object, std::string_view key) {
  if (!object.is_object()) return "";
  const auto it = object.find(key);
  if (it == object.end()) return "";
  if (it->is_string()) return it->get<std::string>();
  if (it->is_number() || it->is_boolean()) return it->dump();
  if (it->is_array()) {  // e.g. several expected-failures files
    std::string joined;
    for (const Json& item : *it)
      if (item.is_string() || item.is_number()) {
        if (!joined.empty()) joined += ", ";
        joined += item.is_string() ? item.get<std::string>() : item.dump();
      }
    return joined;
  }
  return "";
}

std::optional<double> numberField(const Json& object, std::string_view key) {
  if (!object.is_object()) return std::nullopt;
  const auto it = object.find(key);
  if (it == object.end() || !it->is_number()) return std::nullopt;
  return it->get<double>();
}

std::string joinedField(const Json& object, std::string_view key) {
  std::string text;
  for (const Json& item : arrayField(object, key)) {
    if (!text.empty()) text += ", ";
    text += formatValue(item);
  }
  return text;
}

std::string formatValue(const Json& value, int digits) {
  if (value.is_string()) return value.get<std::string>();
  if (value.is_number_integer()) return value.dump();
  if (value.is_number()) {
    char text[40];
    std::snprintf(text, sizeof text, "%.*g", digits, value.get<double>());
    return text;
  }
  if (value.is_boolean()) return value.dump();
  return "-";
}

std::string formatField(const Json& object, std::string_view key, int digits) {
  if (!object.is_object()) return "-";
  const auto it = object.find(key);
  return it == object.end() ? "-" : formatValue(*it, digits);
}

std::string formatMetric(const Json& metrics, std::string_view key, int digits) {
  if (!metrics.is_object()) return "-";
  const auto it = metrics.find(key);
  if (it == metrics.end()) return "-";
  if (it->is_null()) return "non-finite";
  return formatValue(*it, digits);
}

std::string formatSeconds(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) seconds = 0;
  char text[40];
  std::snprintf(text, sizeof text, "%.3f", seconds);
  return text;
}

Outcome outcomeOf(std::string_view verdict) {
  const auto known = comparison::parseVerdict(verdict);
  return known ? comparison::ciOutcome(*known) : Outcome::Failure;
}

bool needsAttention(std::string_view verdict) {
  const auto known = comparison::parseVerdict(verdict);
  return !known || comparison::needsAttention(*known);
}

bool mutantFailed(std::string_view status) {
  const auto known = comparison::parseMutantStatus(status);
  return !known || comparison::isRunFailure(*known);
}

Outcome mutantOutcome(std::string_view status) {
  const auto known = comparison::parseMutantStatus(status);
  return known ? comparison::ciOutcome(*known) : Outcome::Failure;
}

bool backendFailed(std::string_view status) {
  const auto known = comparison::parseBackendStatus(status);
  return !known || comparison::isRunFailure(*known);
}

Outcome backendOutcome(std::string_view status) {
  const auto known = comparison::parseBackendStatus(status);
  return known ? comparison::ciOutcome(*known) : Outcome::Error;
}

std::vector<std::string> backendOrder(const Json& results) {
  std::vector<std::string> order;
  const auto add = [&](const std::string& name) {
    if (!name.empty() && std::find(order.begin(), order.end(), name) == order.end()) order.push_back(name);
  };
  for (const Json& backend : arrayField(results, "backends")) add(textField(backend, "backend"));
  for (const Json& test : arrayField(results, "tests")) add(textField(test, "backend"));
  for (const Json& mutant : arrayField(results, "mutants")) add(textField(mutant, "backend"));
  return order;
}

}  // namespace reports
