#include "runner/run_merge.h"

#include "comparison/run_status.h"
#include "comparison/verdict.h"
#include "runner/backend_combination.h"
#include "runner/evidence_limit.h"
#include "runner/run_metadata.h"
#include "runner/run_results.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <ostream>
#include <set>
#include <tuple>

namespace runner {
namespace {

using Json = nlohmann::ordered_json;
namespace fs = std::filesystem;
using comparison::BackendStatus;
using comparison::MutantStatus;
using comparison::Verdict;

struct Shard {
  fs::path dir;
  Json results;
  int index = 0;
};

std::string nameOf(const Shard& s) { return s.dir.string(); }

std::string shardName(int index, int total) { return "shard " + std::to_string(index) + "/" + std::to_string(total); }

Shard readShard(const fs::path& dir) {
  const fs::path file = dir / "results.json";
  std::ifstream in(file);
  if (!in) throw MergeRefused(dir.string() + ": no results.json (the shard did not finish, or this is not a run folder)");
  Shard shard{dir, {}, 0};
  try {
    shard.results = Json::parse(in);
  } catch (const Json::parse_error& e) {
    throw MergeRefused(file.string() + ": not JSON: " + e.what());
  }
  const Json& r = shard.results;
  if (!r.is_object() || r.value("format", "") != "lightcts-results")
    throw MergeRefused(file.string() + ": not a lightcts results.json");
  if (!r.contains("shard") || !r["shard"].is_object())
    throw MergeRefused(file.string() + ": not a shard (a run without --shard I/N); there is nothing to merge it with");
  for (const char* key : {"tests", "backends", "mutants"})
    if (!r.contains(key) || !r[key].is_array()) throw MergeRefused(file.string() + ": no \"" + key + "\" array");
  shard.index = r["shard"].value("index", 0);
  return shard;
}

// The same value in every shard, or a refusal naming the first that differs.
void requireSame(const std::vector<Shard>& shards, const std::string& what,
                 const std::function<Json(const Json&)>& field) {
  const Json first = field(shards.front().results);
  for (const Shard& s : shards)
    if (field(s.results) != first)
      throw MergeRefused("different " + what + ": " + first.dump() + " in " + nameOf(shards.front()) + ", " +
                         field(s.results).dump() + " in " + nameOf(s) + "; only shards of one run merge");
}

// Every combination that ran has one device in every shard: its name,
// driver and driver version.
void requireSameDrivers(const std::vector<Shard>& shards) {
  std::map<std::string, std::pair<Json, std::string>> seen;  // suffix -> (device, shard)
  for (const Shard& s : shards)
    for (const Json& b : s.results["backends"]) {
      const Json& d = b["device"];
      if (!d.is_object()) continue;
      const Json driver = {d.value("name", ""), d.value("driver", ""), d.value("driver_version", "")};
      const std::string suffix = b.value("backend", "");
      const auto [it, inserted] = seen.emplace(suffix, std::pair{driver, nameOf(s)});
      if (!inserted && it->second.first != driver)
        throw MergeRefused("different drivers on " + suffix + ": " + it->second.first.dump() + " in " +
                           it->second.second + ", " + driver.dump() + " in " + nameOf(s) +
                           "; only shards of one run merge");
    }
}

// Shards 1..N, each exactly once.
void requireEveryShardOnce(std::vector<Shard>& shards) {
  const int total = shards.front().results["shard"].value("total", 0);
  std::map<int, const Shard*> byIndex;
  for (const Shard& s : shards) {
    if (s.index < 1 || s.index > total) throw MergeRefused(nameOf(s) + ": shard index " + std::to_string(s.index) + " outside 1.." + std::to_string(total));
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
// `--driver` such as zink, which takes the place of the table's GL
// combinations) in the order the shards name them.
std::vector<std::string> combinationOrder(const std::vector<Shard>& shards) {
  std::vector<std::string> suffixes;
  for (const Shard& s : shards)
    for (const Json& b : s.results["backends"]) {
      const std::string suffix = b.value("backend", "");
      if (std::find(suffixes.begin(), suffixes.end(), suffix) == suffixes.end()) suffixes.push_back(suffix);
    }
  std::stable_sort(suffixes.begin(), suffixes.end(),
                   [](const std::string& a, const std::string& b) { return combinationIndex(a) < combinationIndex(b); });
  return suffixes;
}

Json mergeTests(const std::vector<Shard>& shards, const std::vector<std::string>& suffixes) {
  // The order of an unsharded run: combinations as above, then scenes by
  // group and name (conformance::findSceneFiles).
  const auto testOrder = [&](const Json& t) {
    const auto at = std::find(suffixes.begin(), suffixes.end(), t.value("backend", ""));
    return std::tuple(std::size_t(at - suffixes.begin()), t.value("group", ""), t.value("scene", ""));
  };
  std::vector<Json> tests;
  std::map<std::string, std::string> shardOfTest;
  for (const Shard& s : shards)
    for (const Json& t : s.results["tests"]) {
      const std::string name = t.value("name", "");
      const auto [it, inserted] = shardOfTest.emplace(name, nameOf(s));
      if (!inserted) throw MergeRefused("test " + name + " is in two shards: " + it->second + " and " + nameOf(s));
      tests.push_back(t);
    }
  const std::size_t expected = shards.front().results["shard"].value("tests_in_run", std::size_t(0));
  if (tests.size() != expected)
    throw MergeRefused("the shards hold " + std::to_string(tests.size()) + " tests where the run has " +
                       std::to_string(expected));
  std::stable_sort(tests.begin(), tests.end(), [&](const Json& a, const Json& b) { return testOrder(a) < testOrder(b); });
  Json merged = Json::array();
  for (Json& t : tests) merged.push_back(std::move(t));
  return merged;
}

// One combination over every shard that ran some of its scenes.
Json mergeBackend(const std::string& suffix, const std::vector<const Json*>& parts, const Json& tests,
                  const Json& mutantCounts) {
  const Json& first = *parts.front();
  BackendStatus status = BackendStatus::Ran;
  std::string message;
  bool anyRan = false, anyAbsent = false;
  Json device = nullptr;
  double wall = 0;
  for (const Json* b : parts) {
    const auto s = comparison::parseBackendStatus(b->value("status", "")).value_or(BackendStatus::Error);
    if (device.is_null()) device = (*b)["device"];
    wall += b->value("wall_s", 0.0);
    anyRan = anyRan || s == BackendStatus::Ran;
    anyAbsent = anyAbsent || s == BackendStatus::NotSupported;
    if (s == BackendStatus::Error && status != BackendStatus::Error) {
      status = BackendStatus::Error;
      message = b->value("message", "");
    }
  }
  if (status != BackendStatus::Error && anyAbsent) {
    status = anyRan ? BackendStatus::Error : BackendStatus::NotSupported;
    for (const Json* b : parts)
      if (b->value("status", "") == comparison::backendStatusName(BackendStatus::NotSupported)) {
        message = (anyRan ? "absent in some shards: " : "") + b->value("message", "");
        break;
      }
  }
  std::map<Verdict, int> counted;
  for (const Json& t : tests)
    if (t.value("backend", "") == suffix)
      ++counted[comparison::parseVerdict(t.value("verdict", "")).value_or(Verdict::Crash)];
  return {{"backend", suffix},
          {"api_backend", first["api_backend"]},
          {"driver_option", first["driver_option"]},
          {"status", comparison::backendStatusName(status)},
          {"message", message},
          {"device", device},
          {"expected_failures_file", first["expected_failures_file"]},
          {"counts", countsJson(counted)},
          {"mutant_counts", mutantCounts},
          {"wall_s", wall},
          {"log", "logs/" + suffix + ".log"}};
}

struct MergedMutant {
  Json record;
  const Shard* evidenceShard = nullptr;  // whose mutants/<mutant>.<suffix> the record's evidence is
};

// A mutant on one combination over the shards: killed when any shard killed
// it (killed_by in the unsharded order, the evidence of the first kill);
// else NotSupported when every shard says so; else Crash, Timeout, Survived.
MergedMutant mergeMutant(const std::vector<std::pair<const Json*, const Shard*>>& records,
                         const std::map<std::string, std::size_t>& sceneOrder) {
  std::vector<std::string> killedBy;
  const Shard* evidenceShard = nullptr;
  Json evidence = nullptr;
  std::size_t firstKill = SIZE_MAX;
  bool allAbsent = true, crashed = false, timedOut = false;
  for (const auto& [r, shard] : records) {
    const auto status = comparison::parseMutantStatus(r->value("status", "")).value_or(MutantStatus::Crash);
    allAbsent = allAbsent && status == MutantStatus::NotSupported;
    crashed = crashed || status == MutantStatus::Crash;
    timedOut = timedOut || status == MutantStatus::Timeout;
    for (const Json& scene : (*r)["killed_by"]) killedBy.push_back(scene.get<std::string>());
    if ((*r)["killed_by"].empty() || (*r)["evidence"].is_null()) continue;
    const auto at = sceneOrder.find((*r)["killed_by"][0].get<std::string>());
    const std::size_t order = at == sceneOrder.end() ? SIZE_MAX - 1 : at->second;
    if (order < firstKill) {
      firstKill = order;
      evidence = (*r)["evidence"];
      evidenceShard = shard;
    }
  }
  auto rank = [&](const std::string& scene) {
    const auto at = sceneOrder.find(scene);
    return at == sceneOrder.end() ? SIZE_MAX : at->second;
  };
  std::stable_sort(killedBy.begin(), killedBy.end(),
                   [&](const std::string& a, const std::string& b) { return rank(a) < rank(b); });
  const MutantStatus status = !killedBy.empty() ? MutantStatus::Killed
                              : allAbsent       ? MutantStatus::NotSupported
                              : crashed         ? MutantStatus::Crash
                              : timedOut        ? MutantStatus::Timeout
                                                : MutantStatus::Survived;
  const Json& first = *records.front().first;
  Json record = {{"mutant", first["mutant"]},
                 {"what", first["what"]},
                 {"backend", first["backend"]},
                 {"status", comparison::mutantStatusName(status)},
                 {"killers", first.contains("killers") ? first["killers"] : Json::array()},
                 {"killed_by", killedBy},
                 {"evidence", evidence}};
  return {std::move(record), evidenceShard};
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
      all << "==== " << shardName(s.index, s.results["shard"].value("total", 0)) << " (" << s.dir.string() << ")\n"
          << in.rdbuf();
    }
  }
}

bool mergedRunPasses(const Json& merged) {
  const bool flakesFail = merged.value("flakes_fail", false);
  for (const Json& t : merged["tests"]) {
    const Verdict v = comparison::parseVerdict(t.value("verdict", "")).value_or(Verdict::Crash);
    if (comparison::isRunFailure(v) || (flakesFail && v == Verdict::Flake)) return false;
  }
  for (const Json& b : merged["backends"])
    if (comparison::isRunFailure(comparison::parseBackendStatus(b.value("status", "")).value_or(BackendStatus::Error)))
      return false;
  for (const Json& m : merged["mutants"])
    if (comparison::isRunFailure(comparison::parseMutantStatus(m.value("status", "")).value_or(MutantStatus::Crash)))
      return false;
  return true;
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
  requireSame(shards, "lightcts revisions", [](const Json& r) { return r["lightcts_revision"]; });
  requireSame(shards, "scene sets (scenes_digest)", [](const Json& r) { return r.value("scenes_digest", Json()); });
  requireSame(shards, "shard counts", [](const Json& r) { return r["shard"]["total"]; });
  requireSame(shards, "partitions (each shard must get the same backends, mutants and --timings file)",
              [](const Json& r) { return r["shard"]["partition"]; });
  requireSameDrivers(shards);
  requireEveryShardOnce(shards);
  // What chose and judged the tests must be the same in every shard (the
  // partition digest covers the tests, not the baselines that judge them).
  requireSame(shards, "baseline files (expected failures, caselists)",
              [](const Json& r) { return r.value("baseline_files", Json::array()); });
  requireSame(shards, "selections", [](const Json& r) { return r.value("selection", Json()); });
  requireSame(shards, "mutation checks (killers or all scenes)", [](const Json& r) { return r.value("mutant_check", Json()); });
  const std::vector<std::string> suffixes = combinationOrder(shards);  // in the unsharded run's order
  Json tests = mergeTests(shards, suffixes);

  // The unsharded order of scenes, for killed_by and the first kill.
  std::map<std::string, std::size_t> sceneOrder;
  {
    std::set<std::pair<std::string, std::string>> scenes;
    for (const Json& t : tests) scenes.emplace(t.value("group", ""), t.value("scene", ""));
    for (const auto& [group, scene] : scenes) sceneOrder.emplace(group + "." + scene, sceneOrder.size());
  }
  const Json& first = shards.front().results;
  const std::vector<std::string> mutantOrder = first.value("mutants_run", std::vector<std::string>{});

  Json backends = Json::array();
  Json mutants = Json::array();
  std::vector<MergedMutant> mergedMutants;
  for (const std::string& suffix : suffixes) {
    std::vector<const Json*> parts;
    for (const Shard& s : shards)
      for (const Json& b : s.results["backends"])
        if (b.value("backend", "") == suffix) parts.push_back(&b);
    std::vector<const Json*> records;
    const std::size_t firstMutant = mergedMutants.size();
    for (const std::string& mutant : mutantOrder) {
      std::vector<std::pair<const Json*, const Shard*>> shardRecords;
      for (const Shard& s : shards)
        for (const Json& m : s.results["mutants"])
          if (m.value("mutant", "") == mutant && m.value("backend", "") == suffix) shardRecords.emplace_back(&m, &s);
      if (!shardRecords.empty()) mergedMutants.push_back(mergeMutant(shardRecords, sceneOrder));
    }
    for (std::size_t k = firstMutant; k < mergedMutants.size(); ++k) records.push_back(&mergedMutants[k].record);
    backends.push_back(mergeBackend(suffix, parts, tests, mutantCountsJson(records)));
  }
  for (const MergedMutant& m : mergedMutants) mutants.push_back(m.record);

  std::string startedUtc = first.value("started_utc", "");
  double longest = 0;
  Json mergedFrom = Json::array();
  for (const Shard& s : shards) {
    startedUtc = std::min(startedUtc, s.results.value("started_utc", startedUtc));
    longest = std::max(longest, s.results.value("duration_s", 0.0));
    mergedFrom.push_back({{"dir", s.dir.string()},
                          {"shard", s.results["shard"]},
                          {"duration_s", s.results["duration_s"]},
                          {"machine", s.results["machine"]}});
  }
  // Each shard computed the light budgets of the scenes it held; a scene
  // split across shards has the same budgets in each (they do not depend on
  // the backend), so the first one stays.
  Json budgets = Json::object();
  for (const Shard& s : shards)
    if (s.results.contains("budgets"))
      for (const auto& [scene, budget] : s.results["budgets"].items())
        if (!budgets.contains(scene)) budgets[scene] = budget;
  Json merged = {{"format", "lightcts-results"},
                 {"version", 1},
                 {"lightcts_revision", first["lightcts_revision"]},
                 {"started_utc", startedUtc},
                 {"duration_s", longest},  // the longest shard: the run's wall time when they ran at once
                 {"command", options.commandLine},
                 {"machine", first["machine"]},
                 {"scenes_dir", first["scenes_dir"]},
                 {"scenes_digest", first["scenes_digest"]},
                 {"selection", first.contains("selection") ? first["selection"] : Json(nullptr)},
                 {"baseline_files", first.contains("baseline_files") ? first["baseline_files"] : Json::array()},
                 {"mutants_run", first["mutants_run"]},
                 {"mutant_check", first.value("mutant_check", "all-scenes")},
                 {"mutants_not_checked", first.contains("mutants_not_checked") ? first["mutants_not_checked"] : Json::array()},
                 {"evidence_limit", first.contains("evidence_limit") ? first["evidence_limit"] : Json(nullptr)},
                 {"evidence_url", options.evidenceUrl.empty() ? first.value("evidence_url", "") : options.evidenceUrl},
                 {"jobs", first["jobs"]},
                 {"shard", nullptr},
                 {"merged_from", mergedFrom},
                 {"reference_cache", first["reference_cache"]},
                 {"timeout_s", first["timeout_s"]},
                 {"flake_retries", first["flake_retries"]},
                 {"flakes_fail", first["flakes_fail"]},
                 {"backends", backends},
                 {"tests", tests},
                 {"mutants", mutants},
                 {"budgets", budgets},
                 {"slowest", slowestTests(tests)}};

  // Everything checked: now the folder is written.
  fs::create_directories(outDir);
  removeStaleRunOutputs(outDir);
  for (const Shard& s : shards) copyFolder(s.dir / "evidence", outDir / "evidence");
  for (const Shard& s : shards) copyFolder(s.dir / "budgets", outDir / "budgets");
  for (const MergedMutant& m : mergedMutants) {
    if (!m.evidenceShard) continue;
    const std::string name = m.record["mutant"].get<std::string>() + "." + m.record["backend"].get<std::string>();
    copyFolder(m.evidenceShard->dir / "mutants" / name, outDir / "mutants" / name);
  }
  // Each shard kept the images of at most --evidence-limit failures; the
  // merged run keeps at most that many in all, the first in its order.
  if (merged["evidence_limit"].is_number_integer())
    limitEvidenceImages(merged["tests"], outDir, merged["evidence_limit"].get<int>());
  mergeLogs(shards, outDir / "logs");
  writeRunOutputs(merged, outDir);

  const bool passes = mergedRunPasses(merged);
  for (const Json& b : backends) {
    out << "merge: " << b["backend"].get<std::string>() << ": " << b["status"].get<std::string>();
    for (auto it = b["counts"].begin(); it != b["counts"].end(); ++it)
      if (it.value().get<int>() > 0) out << ", " << it.value().get<int>() << " " << it.key();
    if (!mutantOrder.empty())
      out << "; mutants: " << b["mutant_counts"]["killed"].get<int>() << " killed, "
          << b["mutant_counts"]["survived"].get<int>() << " survived";
    out << "\n";
  }
  out << "merge: " << shards.size() << " shard(s), " << tests.size() << " test(s) into "
      << (outDir / "results.json").string() << ", report in " << (outDir / "report" / "index.html").string()
      << std::endl;
  return passes ? 0 : 1;
}

}  // namespace runner
