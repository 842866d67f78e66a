#include "runner/test_selection.h"

#include <fnmatch.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace runner {
namespace {

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

bool anyMatches(const std::vector<NamePattern>& patterns, const std::string& name) {
  return std::any_of(patterns.begin(), patterns.end(),
                     [&](const NamePattern& p) { return globMatches(p.glob, name); });
}

// Every pattern must match some name of the run: one that matches nothing
// names a test that is not there.
void requireEachMatches(const std::vector<NamePattern>& patterns, const std::vector<std::string>& names) {
  for (const NamePattern& p : patterns)
    if (std::none_of(names.begin(), names.end(), [&](const std::string& n) { return globMatches(p.glob, n); }))
      throw std::invalid_argument(p.source + ": '" + p.glob + "' matches no test of this run");
}

}  // namespace

bool globMatches(const std::string& glob, const std::string& name) {
  return ::fnmatch(glob.c_str(), name.c_str(), 0) == 0;
}

void TestSelection::include(const std::string& glob) { includes_.push_back({glob, "--include"}); }

void TestSelection::exclude(const std::string& glob) { excludes_.push_back({glob, "--exclude"}); }

void TestSelection::loadCaselist(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::invalid_argument("--caselist: cannot read " + file.string());
  std::ostringstream text;
  text << in.rdbuf();
  parseCaselist(text.str(), file.string());
  caselistFiles_.push_back(file.string());
}

void TestSelection::parseCaselist(const std::string& text, const std::string& sourceName) {
  std::istringstream in(text);
  int lineNumber = 0;
  std::size_t before = caselist_.size();
  for (std::string line; std::getline(in, line);) {
    ++lineNumber;
    const std::string name = trimmed(line.substr(0, line.find('#')));
    if (name.empty()) continue;
    if (name.find_first_of(" \t") != std::string::npos)
      throw std::invalid_argument(sourceName + ":" + std::to_string(lineNumber) + ": '" + name +
                                  "': one test name or glob a line");
    caselist_.push_back({name, sourceName + ":" + std::to_string(lineNumber)});
  }
  if (caselist_.size() == before) throw std::invalid_argument(sourceName + ": no test name in the caselist");
}

std::vector<bool> TestSelection::select(const std::vector<std::string>& names) const {
  requireEachMatches(caselist_, names);
  requireEachMatches(includes_, names);
  std::vector<bool> chosen(names.size());
  bool any = false;
  for (std::size_t i = 0; i < names.size(); ++i) {
    chosen[i] = (caselist_.empty() || anyMatches(caselist_, names[i])) &&
                (includes_.empty() || anyMatches(includes_, names[i])) && !anyMatches(excludes_, names[i]);
    any = any || chosen[i];
  }
  if (!any && !names.empty()) throw std::invalid_argument("the selection (--include, --exclude, --caselist) leaves no test");
  return chosen;
}

results::SelectionRecord TestSelection::record() const {
  auto globs = [](const std::vector<NamePattern>& patterns) {
    std::vector<std::string> list;
    for (const NamePattern& p : patterns) list.push_back(p.glob);
    return list;
  };
  return {globs(includes_), globs(excludes_), caselistFiles_};
}

}  // namespace runner
