// Expected failures of a driver (docs/vendors.md), in the baseline style of
// Mesa's deqp-runner: one `test,Status` line per known failure, each with the
// reason beside it after '#'. A listed test that fails with that status
// becomes ExpectedFail; a listed test that passes becomes UnexpectedPass, so
// a fixed bug is noticed and the line removed.
//
// A driver's deviation does not go away under a legal implementation, so a
// line for <group>.<name>.<suffix> also covers the admissible variants' tests
// of that scene (<group>.<name>@<variant>.<suffix>), unless a line names the
// variant's test itself. Such an inherited line makes a failure
// ExpectedFail, but a pass stays Pass: a variant may well step around the
// driver's fault.
//
//   # lavapipe, Mesa 22.3.6
//   stability.range-1e4.vulkan,Fail  # lavapipe flushes denormals in the range term
#pragma once

#include "comparison/verdict.h"

#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace runner {

struct ExpectedFailure {
  comparison::Verdict status = comparison::Verdict::Fail;  // one that comparison::isExpectable
  std::string reason;
  std::string source;  // file:line, for messages
  bool inherited = false;  // a variant's test, covered by its scene's line
};

class ExpectedFailures {
 public:
  // Throws std::runtime_error naming file and line for a malformed line, an
  // unknown status, a missing reason or a test listed twice.
  void load(const std::filesystem::path& file);
  void parse(const std::string& text, const std::string& sourceName);

  const ExpectedFailure* find(const std::string& test) const;
  bool empty() const { return entries_.empty(); }
  const std::vector<std::string>& files() const { return files_; }

 private:
  std::map<std::string, ExpectedFailure> entries_;
  std::map<std::string, ExpectedFailure> inherited_;  // every variant's test of each listed test
  std::vector<std::string> files_;
};

// The verdict after the baseline: raw Pass of a listed test is
// UnexpectedPass (Pass where the line is inherited); the listed status is
// ExpectedFail; anything else stays.
comparison::Verdict applyExpectation(comparison::Verdict rawVerdict, const ExpectedFailure* expected);

}  // namespace runner
