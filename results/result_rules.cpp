#include "results/result_rules.h"

#include <algorithm>

namespace results {

using comparison::AdmissibleStatus;
using comparison::BackendStatus;
using comparison::MutantStatus;
using comparison::Verdict;

StatusAndMessage combinedBackendStatus(const std::vector<StatusAndMessage>& parts, std::string_view absentInSome) {
  StatusAndMessage combined;
  bool anyRan = false, anyAbsent = false;
  for (const StatusAndMessage& part : parts) {
    anyRan = anyRan || part.status == BackendStatus::Ran;
    anyAbsent = anyAbsent || part.status == BackendStatus::NotSupported;
    if (part.status == BackendStatus::Error && combined.status != BackendStatus::Error) combined = part;
  }
  if (combined.status == BackendStatus::Error || !anyAbsent) return combined;
  combined.status = anyRan ? BackendStatus::Error : BackendStatus::NotSupported;
  for (const StatusAndMessage& part : parts)
    if (part.status == BackendStatus::NotSupported) {
      combined.message = (anyRan ? std::string(absentInSome) : std::string()) + part.message;
      break;
    }
  return combined;
}

MutantStatus mutantStatus(const MutantObservations& seen) {
  return seen.killed          ? MutantStatus::Killed
         : seen.backendAbsent ? MutantStatus::NotSupported
         : seen.crashed       ? MutantStatus::Crash
         : seen.timedOut      ? MutantStatus::Timeout
         : seen.notRun        ? MutantStatus::NotRun
                              : MutantStatus::Survived;
}

MutantObservations observationsOf(MutantStatus status) {
  return {status == MutantStatus::Killed, status == MutantStatus::NotSupported, status == MutantStatus::Crash,
          status == MutantStatus::Timeout, status == MutantStatus::NotRun};
}

MutantObservations joined(const MutantObservations& a, const MutantObservations& b) {
  // Absent only where every part was: a backend present in one shard checked the mutant there.
  return {a.killed || b.killed, a.backendAbsent && b.backendAbsent, a.crashed || b.crashed, a.timedOut || b.timedOut,
          a.notRun || b.notRun};
}

bool passed(Verdict raw) { return raw == Verdict::Pass || raw == Verdict::QualityWarning; }

bool failedAttempt(Verdict raw) { return raw == Verdict::Fail || raw == Verdict::Crash || raw == Verdict::Timeout; }

std::map<Verdict, int> countVerdicts(const std::vector<TestRecord>& tests, std::string_view backend) {
  std::map<Verdict, int> counts;
  for (const TestRecord& t : tests)
    if (t.backend == backend && t.admissible.empty()) ++counts[t.verdict];
  return counts;
}

std::map<Verdict, int> countAdmissibleVerdicts(const std::vector<TestRecord>& tests, std::string_view backend) {
  std::map<Verdict, int> counts;
  for (const TestRecord& t : tests)
    if (t.backend == backend && !t.admissible.empty()) ++counts[t.verdict];
  return counts;
}

std::vector<AdmissibleRecord> admissibleRecords(const std::vector<TestRecord>& tests) {
  std::vector<AdmissibleRecord> records;
  struct Seen {
    bool failed = false, broke = false, present = false;
  };
  std::vector<Seen> seen;
  for (const TestRecord& t : tests) {
    if (t.admissible.empty()) continue;
    auto it = std::find_if(records.begin(), records.end(), [&](const AdmissibleRecord& r) {
      return r.variant == t.admissible && r.backend == t.backend;
    });
    if (it == records.end()) {
      AdmissibleRecord record;
      record.variant = t.admissible;
      record.backend = t.backend;
      records.push_back(std::move(record));
      seen.emplace_back();
      it = records.end() - 1;
    }
    Seen& s = seen[std::size_t(it - records.begin())];
    ++it->tests;
    if (t.verdict == Verdict::ExpectedFail) it->expected.push_back(t.name);
    if (comparison::isRunFailure(t.verdict)) {
      it->failed.push_back(t.name);
      s.failed = s.failed || t.verdict == Verdict::Fail || t.verdict == Verdict::UnexpectedPass;
      s.broke = true;
    }
    s.present = s.present || t.verdict != Verdict::NotSupported;
  }
  for (std::size_t i = 0; i < records.size(); ++i)
    records[i].status = seen[i].failed    ? AdmissibleStatus::Unsound
                        : seen[i].broke   ? AdmissibleStatus::Incomplete
                        : !seen[i].present ? AdmissibleStatus::NotSupported
                                           : AdmissibleStatus::Sound;
  return records;
}

MutantCounts countMutants(const std::vector<MutantRecord>& mutants, std::string_view backend) {
  MutantCounts counts;
  for (const MutantRecord& m : mutants) {
    if (m.backend != backend) continue;
    int& bucket = m.status == MutantStatus::Killed     ? counts.killed
                  : m.status == MutantStatus::Survived ? counts.survived
                                                       : counts.other;
    ++bucket;
  }
  return counts;
}

bool runPasses(const RunRecord& run) {
  for (const TestRecord& t : run.tests)
    if (comparison::isRunFailure(t.verdict) || (run.flakesFail && t.verdict == Verdict::Flake)) return false;
  for (const BackendRecord& b : run.backends)
    if (comparison::isRunFailure(b.status)) return false;
  for (const MutantRecord& m : run.mutants) {
    const bool provesNothingYet = run.isShard() && m.status == MutantStatus::Survived;
    if (comparison::isRunFailure(m.status) && !provesNothingYet) return false;
  }
  return true;
}

}  // namespace results
