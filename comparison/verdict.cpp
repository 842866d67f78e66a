#include "comparison/verdict.h"

#include <stdexcept>

namespace comparison {

std::string_view verdictName(Verdict verdict) {
  switch (verdict) {
    case Verdict::Pass: return "Pass";
    case Verdict::Fail: return "Fail";
    case Verdict::QualityWarning: return "QualityWarning";
    case Verdict::NotSupported: return "NotSupported";
    case Verdict::Crash: return "Crash";
    case Verdict::Timeout: return "Timeout";
    case Verdict::ExpectedFail: return "ExpectedFail";
    case Verdict::UnexpectedPass: return "UnexpectedPass";
    case Verdict::Flake: return "Flake";
    case Verdict::NotRun: return "NotRun";
  }
  throw std::invalid_argument("verdictName: not a Verdict");
}

std::optional<Verdict> parseVerdict(std::string_view name) {
  for (const Verdict verdict : kAllVerdicts)
    if (verdictName(verdict) == name) return verdict;
  return std::nullopt;
}

std::ostream& operator<<(std::ostream& out, Verdict verdict) { return out << verdictName(verdict); }

// The switches below list every verdict without a default, so that the
// compiler (-Wswitch) points at each of them when a verdict is added.
bool isRunFailure(Verdict verdict) {
  switch (verdict) {
    case Verdict::Fail:
    case Verdict::Crash:
    case Verdict::Timeout:
    case Verdict::UnexpectedPass:
    case Verdict::NotRun: return true;
    case Verdict::Pass:
    case Verdict::QualityWarning:
    case Verdict::NotSupported:
    case Verdict::ExpectedFail:
    case Verdict::Flake: return false;
  }
  return true;
}

CiOutcome ciOutcome(Verdict verdict) {
  switch (verdict) {
    case Verdict::Pass:
    case Verdict::Flake: return CiOutcome::Pass;
    // pytest's xfail convention: a known failure is not a pass, and must not
    // block. A QualityWarning likewise: a comparison that checked nothing is
    // no pass either (SPEC 7), and no failure of the implementation.
    case Verdict::NotSupported:
    case Verdict::QualityWarning:
    case Verdict::ExpectedFail: return CiOutcome::Skipped;
    // The test did not run to its end.
    case Verdict::Crash:
    case Verdict::Timeout:
    case Verdict::NotRun: return CiOutcome::Error;
    case Verdict::Fail:
    case Verdict::UnexpectedPass: return CiOutcome::Failure;
  }
  return CiOutcome::Failure;
}

bool needsAttention(Verdict verdict) {
  switch (verdict) {
    // A test that never ran has no evidence to look at; the report counts it.
    case Verdict::Pass:
    case Verdict::NotSupported:
    case Verdict::ExpectedFail:
    case Verdict::NotRun: return false;
    case Verdict::Fail:
    case Verdict::QualityWarning:
    case Verdict::Crash:
    case Verdict::Timeout:
    case Verdict::UnexpectedPass:
    case Verdict::Flake: return true;
  }
  return true;
}

bool isExpectable(Verdict verdict) {
  switch (verdict) {
    case Verdict::Fail:
    case Verdict::QualityWarning:
    case Verdict::Crash:
    case Verdict::Timeout: return true;
    case Verdict::Pass:
    case Verdict::NotSupported:
    case Verdict::ExpectedFail:
    case Verdict::UnexpectedPass:
    case Verdict::Flake:
    case Verdict::NotRun: return false;
  }
  return false;
}

bool listedWhenZero(Verdict verdict) { return verdict != Verdict::Flake && verdict != Verdict::NotRun; }

}  // namespace comparison
