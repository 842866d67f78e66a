#include "runner/expected_failures.h"

#include "shaders/shader_variant.h"

#include <fstream>
#include <optional>
#include <sstream>
#include <string_view>
#include <vector>

namespace runner {
namespace {

std::string trim(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t\r");
  return std::string(text.substr(first, last - first + 1));
}

// "Fail, QualityWarning, Crash or Timeout", for the message about a line
// whose status a baseline may not expect.
std::string expectableNames() {
  std::vector<std::string_view> names;
  for (const comparison::Verdict verdict : comparison::kAllVerdicts)
    if (comparison::isExpectable(verdict)) names.push_back(comparison::verdictName(verdict));
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i)
    text += std::string(i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + std::string(names[i]);
  return text;
}

}  // namespace

void ExpectedFailures::load(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read expected-failures file " + file.string());
  std::stringstream text;
  text << in.rdbuf();
  parse(text.str(), file.string());
  files_.push_back(file.string());
}

void ExpectedFailures::parse(const std::string& text, const std::string& sourceName) {
  std::istringstream lines(text);
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    const std::string where = sourceName + ":" + std::to_string(number);
    const auto hash = line.find('#');
    const std::string entry = trim(std::string_view(line).substr(0, hash));
    if (entry.empty()) continue;  // blank or comment-only
    const std::string reason = hash == std::string::npos ? "" : trim(std::string_view(line).substr(hash + 1));
    const auto comma = entry.find(',');
    if (comma == std::string::npos)
      throw std::runtime_error(where + ": expected 'test,Status  # reason', got '" + entry + "'");
    const std::string test = trim(std::string_view(entry).substr(0, comma));
    const std::string status = trim(std::string_view(entry).substr(comma + 1));
    if (test.empty()) throw std::runtime_error(where + ": the test name is empty");
    const std::optional<comparison::Verdict> verdict = comparison::parseVerdict(status);
    if (!verdict || !comparison::isExpectable(*verdict))
      throw std::runtime_error(where + ": unknown status '" + status + "'; expected " + expectableNames());
    if (reason.empty())
      throw std::runtime_error(where + ": '" + test + "' has no reason; write it after '#' on the same line");
    if (const auto it = entries_.find(test); it != entries_.end())
      throw std::runtime_error(where + ": '" + test + "' is listed twice (first at " + it->second.source + ")");
    entries_.emplace(test, ExpectedFailure{*verdict, reason, where});
    if (test.find('@') != std::string::npos) continue;
    const std::size_t dot = test.rfind('.');
    if (dot == std::string::npos) continue;
    for (const shaders::AdmissibleName& variant : shaders::admissibleNames())
      inherited_.emplace(test.substr(0, dot) + "@" + std::string(variant.name) + test.substr(dot),
                         ExpectedFailure{*verdict, reason + " (listed for " + test + ")", where, true});
  }
}

const ExpectedFailure* ExpectedFailures::find(const std::string& test) const {
  if (const auto it = entries_.find(test); it != entries_.end()) return &it->second;
  const auto it = inherited_.find(test);
  return it == inherited_.end() ? nullptr : &it->second;
}

comparison::Verdict applyExpectation(comparison::Verdict rawVerdict, const ExpectedFailure* expected) {
  using comparison::Verdict;
  if (!expected) return rawVerdict;
  if (rawVerdict == Verdict::Pass) return expected->inherited ? Verdict::Pass : Verdict::UnexpectedPass;
  if (rawVerdict == expected->status) return Verdict::ExpectedFail;
  return rawVerdict;
}

}  // namespace runner
