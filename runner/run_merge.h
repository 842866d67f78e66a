// `lightcts merge DIR... --out DIR` (docs/ci.md): joins the
// folders of the N shards of one run (`lightcts run --shard I/N`) into one
// results.json, junit.xml, results.csv, failures.csv and report, as if one
// machine had run it: tests in the unsharded order, counts summed, the kill
// tables of the mutation check joined (a mutant is killed when any shard
// killed it), evidence copied in, each backend's logs concatenated.
//
// It refuses, before writing anything, runs that are not shards of one run:
// different lightcts revisions, scene sets (scenes_digest), drivers (a
// combination's device name, driver or version), partitions (shard total,
// --timings, mutants, backends), a missing or duplicated shard, a test in two
// shards, or fewer tests than the run has.
#pragma once

#include <iosfwd>
#include <stdexcept>
#include <string>
#include <vector>

namespace runner {

struct MergeOptions {
  std::vector<std::string> shardDirs;
  std::string outDir;
  std::string commandLine;  // for results.json
  // --evidence-url for the merged junit.xml; "" keeps the shards' own (the
  // merged folder is usually another CI job's artifact than the shards').
  std::string evidenceUrl;
};

// Why a merge was refused (exit 2): the message names the shard and the difference.
class MergeRefused : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// Exit status as `run`'s: 0 when the merged run passes, 1 when it has a
// failure, an error or a mutant that survived every shard. Throws
// MergeRefused.
int mergeRuns(const MergeOptions& options, std::ostream& out);

}  // namespace runner
