// How `lightcts run` divides its tests: into shards, for CI jobs
// on many machines (`--shard I/N`), and into parts, one worker process each,
// for the cores of one machine (`--jobs N`).
//
// The unit of both is one scene on one backend combination: the model's test
// of that scene and the scene's mutation-check tasks (one per mutant the
// scene is to catch: those it is a killer of, or every mutant with
// --mutants-all-scenes) go together, so a shard checks the mutants of its own
// scenes and the kill table merges (runner/run_merge.h). The parts depend on the plan alone,
// never on --jobs, so a run writes the same files whatever --jobs is.
#pragma once

#include "runner/worker_plan.h"

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace runner {

// One scene on one combination; `tasks` in worker order: the model's test
// (unless --mutants-only), then one task per mutant it checks, in the run's
// mutant order.
struct RunUnit {
  std::size_t combination = 0;  // index into the run's combinations
  std::string test;             // <group>.<name>.<suffix>
  std::vector<WorkerTask> tasks;
};

// --shard I/N, I from 1 (GitLab's CI_NODE_INDEX is 1-based).
struct ShardSpec {
  int index = 1;
  int total = 1;
};
// "I/N" with 1 <= I <= N; throws std::invalid_argument otherwise.
ShardSpec parseShard(const std::string& text);

// Per-test milliseconds of an earlier run (its results.json's timings_ms.total
// and timings_ms.reference): what --timings balances by.
struct TestTiming {
  double totalMs = 0;
  double referenceMs = 0;
};
using Timings = std::map<std::string, TestTiming>;
// Read by results/results_file.h: throws std::invalid_argument "--timings
// FILE: what" when it refuses the file (unreadable, not JSON, not a lightcts
// results.json, a key missing: the message names it).
Timings loadTimings(const std::string& resultsFile);

// The estimated cost of a unit: with timings, its model test's time plus, per
// mutant task, that time less the reference (a mutant reuses the model's
// reference); a test the timings do not know costs the mean of those they do.
// Without timings every task costs 1: the balance is by test count.
std::vector<double> unitCosts(const std::vector<RunUnit>& units, const std::optional<Timings>& timings);

// Which shard each unit goes to (0-based): longest first (ties in unit order)
// onto the least loaded shard (ties to the lowest index), the greedy rule of
// makespan scheduling. Deterministic: the same units and costs give the same
// partition on every machine, so N jobs given the same --timings file cover
// the run exactly once.
std::vector<int> assignShards(const std::vector<double>& costs, int total);

// A digest naming the partition (the units, in order, and each one's shard),
// so that `merge` can tell shards of one partition from those of another.
std::string partitionDigest(const std::vector<RunUnit>& units, const std::vector<int>& shardOfUnit, int total);

// A worker's share of one combination: the model's tests in runs of at most
// `perPart` (in catalogue order; kModelTestsPerPart unless `run
// --tests-per-worker` says), then the mutants, each whole in one part (so a
// mutant's evidence is that of its first kill), consecutive mutants packed
// into parts of at most `perPart` tasks (a mutant with more tasks, checked
// against every scene, has a part of its own). A part is one worker
// process: fewer, longer parts start the driver and compile its pipelines
// fewer times (SwiftShader compiles a pipeline's shaders at its first draw
// in every process), more parts spread a combination over --jobs.
inline constexpr std::size_t kModelTestsPerPart = 24;
struct WorkerPart {
  std::size_t combination = 0;
  int number = 0;  // within the combination, from 0
  std::vector<WorkerTask> tasks;
};
std::vector<WorkerPart> workerParts(const std::vector<RunUnit>& units, std::size_t combinations,
                                    std::size_t perPart = kModelTestsPerPart);

}  // namespace runner
