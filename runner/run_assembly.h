// The fourth step of `lightcts run`: results.json's records from what the
// workers said. A test's verdict after its expected-failures line and its
// retries; a mutant's status on each combination from its tasks against
// the model's verdicts; a backend's counts from those records
// (results/result_rules.h, the rules `merge` applies too).
#pragma once

#include "results/run_records.h"
#include "runner/run_execution.h"

#include <string>
#include <vector>

namespace runner {

struct AssembledRecords {
  std::vector<results::TestRecord> tests;
  std::vector<results::BackendRecord> backends;
  std::vector<results::MutantRecord> mutants;
  std::vector<std::string> flakes;  // "test: Crash, Pass": each Flake's attempts, for the summary
};

AssembledRecords assembleRecords(const RunInputs& inputs, const RunUnits& plan, const std::vector<CombinationRun>& runs);

}  // namespace runner
