// Choosing tests by name (SPEC 8), as deqp-runner and VK-GL-CTS do: shell-style
// globs (fnmatch(3)) on `<group>.<name>.<backend>`. Every way of choosing
// (--include, --exclude, --caselist) reduces to one list of names, decided
// before sharding and before any worker starts, so `--shard I/N` partitions
// the selected tests and the shards of a selection merge into the selection.
//
// A test is selected when it matches a line of the caselists (all of them
// together: one list) when any is given, and an --include glob when any is
// given, and no --exclude glob. An --include glob or a caselist line that matches none of
// the run's tests is a mistake (a typo, a test that was renamed): bad input,
// named with its file and line.
#pragma once

#include "results/run_records.h"

#include <filesystem>
#include <string>
#include <vector>

namespace runner {

struct NamePattern {
  std::string glob;
  std::string source;  // "--include", "--exclude" or "FILE:LINE"
};

class TestSelection {
 public:
  void include(const std::string& glob);
  void exclude(const std::string& glob);
  // A name or glob a line; '#' starts a comment; blank lines are skipped.
  // Throws std::invalid_argument when the file cannot be read or holds no name.
  void loadCaselist(const std::filesystem::path& file);
  void parseCaselist(const std::string& text, const std::string& sourceName);

  // Whether anything narrows the run (otherwise every test is selected).
  bool narrows() const { return !includes_.empty() || !excludes_.empty() || !caselist_.empty(); }

  // Per name, whether it is selected. Throws std::invalid_argument naming the
  // first --include glob or caselist line (file:line) that matches no name,
  // or saying that the selection leaves no test.
  std::vector<bool> select(const std::vector<std::string>& names) const;

  // For results.json: the globs and files as given.
  results::SelectionRecord record() const;
  const std::vector<std::string>& caselistFiles() const { return caselistFiles_; }

 private:
  std::vector<NamePattern> includes_;
  std::vector<NamePattern> excludes_;
  std::vector<NamePattern> caselist_;
  std::vector<std::string> caselistFiles_;
};

// Shell-style glob match of a whole test name (fnmatch(3), no flags: '*'
// crosses the dots of a test name).
bool globMatches(const std::string& glob, const std::string& name);

}  // namespace runner
