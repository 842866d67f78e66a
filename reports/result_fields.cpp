#include "reports/result_fields.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace reports {

std::string formatNumber(double value, int digits) {
  char text[40];
  std::snprintf(text, sizeof text, "%.*g", digits, value);
  return text;
}

std::string formatMeasured(const results::Measured& value, int digits) {
  return value ? formatNumber(*value, digits) : "non-finite";
}

std::string formatOptional(const std::optional<double>& value, int digits) {
  return value ? formatNumber(*value, digits) : "-";
}

std::string formatSeconds(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) seconds = 0;
  char text[40];
  std::snprintf(text, sizeof text, "%.3f", seconds);
  return text;
}

std::string joined(const std::vector<std::string>& items) {
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

std::vector<std::string> backendOrder(const results::RunRecord& run) {
  std::vector<std::string> order;
  const auto add = [&](const std::string& name) {
    if (!name.empty() && std::find(order.begin(), order.end(), name) == order.end()) order.push_back(name);
  };
  for (const results::BackendRecord& backend : run.backends) add(backend.backend);
  for (const results::TestRecord& test : run.tests) add(test.backend);
  for (const results::MutantRecord& mutant : run.mutants) add(mutant.backend);
  return order;
}

}  // namespace reports
