// The second step of `lightcts run`: the selected tests with their
// mutation-check tasks (runner/run_plan.h's units), the mutants the
// selection can check, and with --shard this shard's share.
#pragma once

#include "runner/run_inputs.h"
#include "runner/run_plan.h"
#include "results/run_records.h"

#include <cstddef>
#include <iosfwd>
#include <optional>
#include <set>
#include <utility>
#include <vector>

namespace runner {

struct RunUnits {
  std::vector<RunUnit> units;             // this shard's (every unit without --shard)
  std::size_t testsInRun = 0;             // the tests (model's and variants') of the whole run, every shard's
  std::vector<shaders::Mutant> mutants;   // those asked for that have a scene to run, in the order asked
  std::vector<results::MutantNotChecked> mutantsNotChecked;  // the others, with why
  std::optional<results::ShardRecord> shard;  // none for a whole run
  // The mutants this shard checks on each combination (index): a shard
  // writes no record of a mutant none of whose tasks it holds.
  std::set<std::pair<shaders::Mutant, std::size_t>> mutantChecks;
};

// Throws std::invalid_argument when the selection holds nothing to run, or
// when a mutant asked for by name has no killer among the selected scenes.
// Says on `notes` which mutants are left unchecked.
RunUnits planRunUnits(const RunOptions& options, const RunInputs& inputs, std::ostream& notes);

// --list: the selection as it would run, one test a line (a caselist) on
// `out`, the count on `err`.
void listRunUnits(const RunUnits& plan, std::ostream& out, std::ostream& err);

}  // namespace runner
