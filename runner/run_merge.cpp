#include "runner/run_merge.h"

#include "results/result_rules.h"
#include "results/results_file.h"
#include "results/run_records.h"
#include "runner/backend_combination.h"
#include "runner/evidence_limit.h"
#include "runner/run_results.h"
#include "shaders/shader_variant.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <climits>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <ostream>
#include <set>
#include <tuple>

namespace runner {
namespace {

using Json = nlohmann::ordered_json;
namespace fs = std::filesystem;
using results::BackendRecord;
using results::MutantRecord;
using results::RunRecord;
using results::TestRecord;

struct Shard {
  fs::path dir;
  RunRecord run;
  int index = 0;
  int total = 0;
};

std::string nameOf(const Shard& s) { return s.dir.string(); }

std::string shardName(int index, int total) { return "shard " + std::to_string(index) + "/" + std::to_string(total); }

Shard readShard(const fs::path& dir) {
  const fs::path file = dir / "results.json";
  if (!fs::exists(file))
    throw MergeRefused(dir.string() + ": no results.json (the shard did not finish, or this is not a run folder)");
  Shard shard{dir, {}, 0, 0};
  try {
    shard.run = results::readResultsFile(file);  // a key missing: refused, naming it
  } catch (const results::ResultsFileError& e) {
    throw MergeRefused(e.what());
  }
  if (!shard.run.isShard())
    throw MergeRefused(file.string() + ": not a shard (a run without --shard I/N); there is nothing to merge it with");
  shard.index = int(shard.run.shard->index);
  shard.total = int(shard.run.shard->total);
  return shard;
}

// The same value in every shard, or a refusal naming the first that differs.
void requireSame(const std::vector<Shard>& shards, const std::string& what,
                 const std::function<Json(const RunRecord&)>& field) {
  const Json first = field(shards.front().run);
  for (const Shard& s : shards)
    if (field(s.run) != first)
      throw MergeRefused("different " + what + ": " + first.dump() + " in " + nameOf(shards.front()) + ", " +
                         field(s.run).dump() + " in " + nameOf(s) + "; only shards of one run merge");
}

// Every combination that ran has one device in every shard: its name,
// driver and driver version.
void requireSameDrivers(const std::vector<Shard>& shards) {
  std::map<std::string, std::pair<Json, std::string>> seen;  // suffix -> (device, shard)
  for (const Shard& s : shards)
    for (const BackendRecord& b : s.run.backends) {
      if (!b.device) continue;
      const Json driver = {b.device->name, b.device->driver, b.device->driverVersion};
      const auto [it, inserted] = seen.emplace(b.backend, std::pair{driver, nameOf(s)});
      if (!inserted && it->second.first != driver)
        throw MergeRefused("different drivers on " + b.backend + ": " + it->second.first.dump() + " in " +
                           it->second.second + ", " + driver.dump() + " in " + nameOf(s) +
                           "; only shards of one run merge");
    }
}

// Shards 1..N, each exactly once.
void requireEveryShardOnce(std::vector<Shard>& shards) {
  const int total = shards.front().total;
  std::map<int, const Shard*> byIndex;
  for (const Shard& s : shards) {
    if (s.index < 1 || s.index > total)
      throw MergeRefused(nameOf(s) + ": shard index " + std::to_string(s.index) + " outside 1.." + std::to_string(total));
    const auto [it, inserted] = byIndex.emplace(s.index, &s);
    if (!inserted)
      throw MergeRefused(shardName(s.index, total) + " is given twice: " + nameOf(*it->second) + " and " + nameOf(s));
  }
  std::string missing;
  for (int i = 1; i <= total; ++i)
    if (!byIndex.count(i)) missing += (missing.empty() ? "" : ", ") + shardName(i, total);
  if (!missing.empty()) throw MergeRefused(missing + (missing.find(',') == std::string::npos ? " is" : " are") + " missing");
  std::sort(shards.begin(), shards.end(), [](const Shard& a, const Shard& b) { return a.index < b.index; });
}

std::size_t combinationIndex(const std::string& suffix) {
  const auto& all = backendCombinations();
  for (std::size_t i = 0; i < all.size(); ++i)
    if (all[i].suffix == suffix) return i;
  return all.size();
}

// The combinations of the run, in the unsharded run's order: the table's
// (runner/backend_combination.h), then those the table does not list (a
// `--driver` that takes the place of the table's GL combinations, such as
// zink on gl-osmesa) in the order the shards name them.
std::vector<std::string> combinationOrder(const std::vector<Shard>& shards) {
  std::vector<std::string> suffixes;
  for (const Shard& s : shards)
    for (const BackendRecord& b : s.run.backends)
      if (std::find(suffixes.begin(), suffixes.end(), b.backend) == suffixes.end()) suffixes.push_back(b.backend);
  std::stable_sort(suffixes.begin(), suffixes.end(),
                   [](const std::string& a, const std::string& b) { return combinationIndex(a) < combinationIndex(b); });
  return suffixes;
}

std::vector<TestRecord> mergeTests(const std::vector<Shard>& shards, const std::vector<std::string>& suffixes) {
  // The order of an unsharded run: combinations as above, the model's
  // tests before each admissible variant's (in the table's order), then
  // scenes by group and name (conformance::findSceneFiles).
  const auto testOrder = [&](const TestRecord& t) {
    const auto at = std::find(suffixes.begin(), suffixes.end(), t.backend);
    const auto variant = shaders::admissibleFromName(t.admissible.empty() ? "none" : t.admissible);
    return std::tuple(std::size_t(at - suffixes.begin()), variant ? int(*variant) : INT_MAX, t.group, t.scene);
  };
  std::vector<TestRecord> tests;
  std::map<std::string, std::string> shardOfTest;
  for (const Shard& s : shards)
    for (const TestRecord& t : s.run.tests) {
      const auto [it, inserted] = shardOfTest.emplace(t.name, nameOf(s));
      if (!inserted) throw MergeRefused("test " + t.name + " is in two shards: " + it->second + " and " + nameOf(s));
      tests.push_back(t);
    }
  const std::size_t expected = std::size_t(std::max(shards.front().run.shard->testsInRun, 0LL));
  if (tests.size() != expected)
    throw MergeRefused("the shards hold " + std::to_string(tests.size()) + " tests where the run has " +
                       std::to_string(expected));
  std::stable_sort(tests.begin(), tests.end(),
                   [&](const TestRecord& a, const TestRecord& b) { return testOrder(a) < testOrder(b); });
  return tests;
}

// One combination over every shard that ran some of its scenes.
BackendRecord mergeBackend(const std::vector<const BackendRecord*>& parts, const std::vector<TestRecord>& tests,
                           const std::vector<MutantRecord>& mutants) {
  BackendRecord merged = *parts.front();
  std::vector<results::StatusAndMessage> statuses;
  merged.device = std::nullopt;
  merged.wallSeconds = 0;
  merged.taskTimes = {};
  for (const BackendRecord* b : parts) {
    statuses.push_back({b->status, b->message});
    if (!merged.device) merged.device = b->device;
    merged.wallSeconds += b->wallSeconds;
    merged.taskTimes += b->taskTimes;
  }
  const results::StatusAndMessage status = results::combinedBackendStatus(statuses, "absent in some shards: ");
  merged.status = status.status;
  merged.message = status.message;
  merged.counts = results::countVerdicts(tests, merged.backend);
  merged.admissibleCounts = results::countAdmissibleVerdicts(tests, merged.backend);
  merged.mutantCounts = results::countMutants(mutants, merged.backend);
  merged.log = "logs/" + merged.backend + ".log";
  return merged;
}

struct MergedMutant {
  MutantRecord record;
  const Shard* evidenceShard = nullptr;  // whose mutants/<mutant>.<suffix> the record's evidence is
};

// A mutant on one combination over the shards (results::mutantStatus over
// the shards' observations joined): killed_by in the unsharded order, the
// evidence of the first kill.
MergedMutant mergeMutant(const std::vector<std::pair<const MutantRecord*, const Shard*>>& records,
                         const std::map<std::string, std::size_t>& sceneOrder) {
  MergedMutant merged{*records.front().first, nullptr};
  MutantRecord& m = merged.record;
  m.killedBy.clear();
  m.evidence = std::nullopt;
  std::size_t firstKill = SIZE_MAX;
  results::MutantObservations seen;
  seen.backendAbsent = true;  // absent only where every shard says so
  for (const auto& [r, shard] : records) {
    seen = results::joined(seen, results::observationsOf(r->status));
    m.killedBy.insert(m.killedBy.end(), r->killedBy.begin(), r->killedBy.end());
    if (r->killedBy.empty() || !r->evidence) continue;
    const auto at = sceneOrder.find(r->killedBy.front());
    const std::size_t order = at == sceneOrder.end() ? SIZE_MAX - 1 : at->second;
    if (order < firstKill) {
      firstKill = order;
      m.evidence = r->evidence;
      merged.evidenceShard = shard;
    }
  }
  auto rank = [&](const std::string& scene) {
    const auto at = sceneOrder.find(scene);
    return at == sceneOrder.end() ? SIZE_MAX : at->second;
  };
  std::stable_sort(m.killedBy.begin(), m.killedBy.end(),
                   [&](const std::string& a, const std::string& b) { return rank(a) < rank(b); });
  seen.killed = !m.killedBy.empty();
  m.status = results::mutantStatus(seen);
  return merged;
}

void copyFolder(const fs::path& from, const fs::path& to) {
  if (!fs::is_directory(from)) return;
  fs::create_directories(to.parent_path());
  fs::copy(from, to, fs::copy_options::recursive | fs::copy_options::overwrite_existing);
}

// out/logs/NAME: every shard's logs/NAME (the backend logs and their
// retries), in shard order, each under a line naming the shard.
void mergeLogs(const std::vector<Shard>& shards, const fs::path& outLogs) {
  std::set<std::string> names;
  for (const Shard& s : shards)
    if (fs::is_directory(s.dir / "logs"))
      for (const fs::directory_entry& e : fs::directory_iterator(s.dir / "logs")) {
        const std::string name = e.path().filename().string();
        if (e.path().extension() == ".log") names.insert(name);
      }
  fs::create_directories(outLogs);
  for (const std::string& name : names) {
    std::ofstream all(outLogs / name, std::ios::trunc);
    for (const Shard& s : shards) {
      std::ifstream in(s.dir / "logs" / name);
      if (!in) continue;
      all << "==== " << shardName(s.index, s.total) << " (" << s.dir.string() << ")\n" << in.rdbuf();
    }
  }
}

}  // namespace

int mergeRuns(const MergeOptions& options, std::ostream& out) {
  if (options.shardDirs.empty()) throw MergeRefused("nothing to merge: give the shards' folders");
  const fs::path outDir(options.outDir);
  std::vector<Shard> shards;
  std::error_code ec;
  for (const std::string& dir : options.shardDirs) {
    if (fs::exists(outDir, ec) && fs::equivalent(dir, outDir, ec))
      throw MergeRefused("--out " + options.outDir + " is one of the shards; merge into another folder");
    shards.push_back(readShard(dir));
  }
  requireSame(shards, "lightcts revisions", [](const RunRecord& r) { return Json(r.lightctsRevision); });
  requireSame(shards, "scene sets (scenes_digest)", [](const RunRecord& r) { return Json(r.scenesDigest); });
  requireSame(shards, "shard counts", [](const RunRecord& r) { return Json(r.shard->total); });
  requireSame(shards, "partitions (each shard must get the same backends, mutants and --timings file)",
              [](const RunRecord& r) { return Json(r.shard->partition); });
  requireSameDrivers(shards);
  requireEveryShardOnce(shards);
  // What chose and judged the tests must be the same in every shard (the
  // partition digest covers the tests, not the baselines that judge them).
  requireSame(shards, "baseline files (expected failures, caselists)", [](const RunRecord& r) {
    Json files = Json::array();
    for (const results::BaselineFile& file : r.baselineFiles) files.push_back(file.toJson());
    return files;
  });
  requireSame(shards, "selections", [](const RunRecord& r) { return r.selection.toJson(); });
  requireSame(shards, "mutation checks (killers or all scenes)", [](const RunRecord& r) { return Json(r.mutantCheck); });
  const std::vector<std::string> suffixes = combinationOrder(shards);  // in the unsharded run's order
  const RunRecord& first = shards.front().run;

  // Everything a whole run says of itself is the first shard's; what the
  // shards did is joined below.
  RunRecord merged = first;
  merged.command = options.commandLine;
  merged.shard = std::nullopt;
  if (!options.evidenceUrl.empty()) merged.evidenceUrl = options.evidenceUrl;
  merged.tests = mergeTests(shards, suffixes);

  // The unsharded order of scenes, for killed_by and the first kill.
  std::map<std::string, std::size_t> sceneOrder;
  {
    std::set<std::pair<std::string, std::string>> scenes;
    for (const TestRecord& t : merged.tests) scenes.emplace(t.group, t.scene);
    for (const auto& [group, scene] : scenes) sceneOrder.emplace(group + "." + scene, sceneOrder.size());
  }

  merged.backends.clear();
  merged.mutants.clear();
  std::vector<MergedMutant> mergedMutants;
  for (const std::string& suffix : suffixes) {
    std::vector<const BackendRecord*> parts;
    for (const Shard& s : shards)
      for (const BackendRecord& b : s.run.backends)
        if (b.backend == suffix) parts.push_back(&b);
    for (const std::string& mutant : first.mutantsRun) {
      std::vector<std::pair<const MutantRecord*, const Shard*>> shardRecords;
      for (const Shard& s : shards)
        for (const MutantRecord& m : s.run.mutants)
          if (m.mutant == mutant && m.backend == suffix) shardRecords.emplace_back(&m, &s);
      if (shardRecords.empty()) continue;
      mergedMutants.push_back(mergeMutant(shardRecords, sceneOrder));
      merged.mutants.push_back(mergedMutants.back().record);
    }
    merged.backends.push_back(mergeBackend(parts, merged.tests, merged.mutants));
  }
  merged.admissible = describedAdmissibleRecords(merged.tests);

  double longest = 0;
  merged.mergedFrom = Json::array();
  for (const Shard& s : shards) {
    merged.startedUtc = std::min(merged.startedUtc, s.run.startedUtc);
    longest = std::max(longest, s.run.durationSeconds);
    merged.mergedFrom.push_back(
        {{"dir", s.dir.string()},
         {"shard", s.run.shard->toJson()},
         {"duration_s", s.run.durationSeconds},
         {"machine", s.run.machine.toJson()}});
  }
  merged.durationSeconds = longest;  // the longest shard: the run's wall time when they ran at once
  // Each shard computed the light budgets of the scenes it held; a scene
  // split across shards has the same budgets in each (they do not depend on
  // the backend), so the first one stays.
  merged.budgets.clear();
  std::set<std::string> budgeted;
  for (const Shard& s : shards)
    for (const results::SceneBudgetRecord& budget : s.run.budgets)
      if (budgeted.insert(budget.scene).second) merged.budgets.push_back(budget);

  // Everything checked: now the folder is written.
  fs::create_directories(outDir);
  removeStaleRunOutputs(outDir);
  for (const Shard& s : shards) copyFolder(s.dir / "evidence", outDir / "evidence");
  for (const Shard& s : shards) copyFolder(s.dir / "budgets", outDir / "budgets");
  for (const MergedMutant& m : mergedMutants) {
    if (!m.evidenceShard) continue;
    const std::string name = m.record.mutant + "." + m.record.backend;
    copyFolder(m.evidenceShard->dir / "mutants" / name, outDir / "mutants" / name);
  }
  // Each shard kept the images of at most --evidence-limit failures; the
  // merged run keeps at most that many in all, the first in its order.
  if (merged.evidenceLimit) limitEvidenceImages(merged.tests, outDir, int(*merged.evidenceLimit));
  mergeLogs(shards, outDir / "logs");
  writeRunOutputs(merged, outDir);

  for (const BackendRecord& b : merged.backends) {
    out << "merge: " << b.backend << ": " << comparison::backendStatusName(b.status)
        << backendCounts(b, !first.mutantsRun.empty()) << "\n";
  }
  for (const std::string& line : admissibleLines(merged.admissible)) out << line << "\n";
  out << "merge: " << shards.size() << " shard(s), " << merged.tests.size() << " test(s) into "
      << (outDir / "results.json").string() << ", report in " << (outDir / "report" / "index.html").string()
      << std::endl;
  return results::runPasses(merged) ? 0 : 1;
}

}  // namespace runner
