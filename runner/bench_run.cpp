#include "runner/bench_run.h"

#include "imaging/atomic_file.h"
#include "reports/bench_report.h"
#include "comparison/run_status.h"
#include "runner/backend_combination.h"
#include "runner/run_metadata.h"
#include "runner/worker_process.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <future>
#include <iomanip>
#include <optional>
#include <ostream>
#include <sstream>

namespace runner {
namespace {

using Json = nlohmann::ordered_json;
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct ProcessOutcome {
  bool ok = false;
  std::string how;  // "exit status 0", "killed by signal ...", "timed out"
  int exitStatus = -1;
  Json output;      // the Google Benchmark JSON it wrote, or null
};

// Runs `lightcts bench-worker ARGS --benchmark_out=FILE` and reads FILE.
ProcessOutcome runBenchProcess(const BenchOptions& options, std::vector<std::string> args, const fs::path& jsonFile,
                               const fs::path& logFile) {
  fs::remove(jsonFile);
  fs::remove(logFile);  // appended to by the process; an earlier run's lines are not this run's
  std::vector<std::string> argv = {options.workerExecutable, "bench-worker"};
  argv.insert(argv.end(), args.begin(), args.end());
  argv.push_back("--benchmark_out=" + jsonFile.string());
  argv.push_back("--benchmark_out_format=json");
  WorkerProcess worker(argv, logFile.string());
  ProcessOutcome outcome;
  const auto deadline = Clock::now() + std::chrono::duration<double>(options.timeoutSeconds);
  std::ofstream console(logFile.string() + ".out");
  std::string line;
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
    const auto status = worker.readLine(std::max(left, std::chrono::milliseconds(1)), line);
    if (status == WorkerProcess::ReadStatus::Line) {
      console << line << '\n';  // Google Benchmark's console table, kept for people
      continue;
    }
    if (status == WorkerProcess::ReadStatus::TimedOut) {
      outcome.how = "timed out after " + std::to_string(int(options.timeoutSeconds)) + " s (" + worker.finish(true) + ")";
      return outcome;
    }
    outcome.how = worker.finish(false);
    break;
  }
  outcome.exitStatus = worker.exitStatus();
  outcome.ok = outcome.exitStatus == 0;
  std::ifstream in(jsonFile);
  if (in) {
    try {
      std::stringstream text;
      text << in.rdbuf();
      // The worker's file reporter (suite/bench/bench_reporters.h) already
      // writes null for a non-finite value; anything else that does not
      // parse is the worker's failure, said as such.
      outcome.output = Json::parse(text.str());
    } catch (const Json::parse_error& e) {
      outcome.ok = false;
      outcome.how += "; its JSON does not parse: " + std::string(e.what());
    }
  } else {
    outcome.ok = false;
  }
  return outcome;
}

// The device lines a frame-benchmark process adds to Google Benchmark's
// context ("<suffix>.device", ".driver", ".api").
Json deviceFromContext(const Json& context, const std::string& suffix) {
  Json device = Json::object();
  for (const auto& [key, field] : {std::pair{".device", "name"}, std::pair{".driver", "driver"},
                                   std::pair{".driver_version", "driver_version"}, std::pair{".api", "api_version"}})
    if (context.contains(suffix + key)) device[field] = context[suffix + key];
  return device;
}

// The name an entry of `suffix`'s process has in the flat top-level array:
// its own when its second part is already the combination suffix (every
// name of frame/<suffix>/... and prepare/cpu/..., docs/bench-format.md), else
// "<suffix>/<name>", so that names stay unique across backends.
std::string flatName(const std::string& name, const std::string& suffix) {
  const std::size_t first = name.find('/');
  if (first != std::string::npos && name.compare(first + 1, suffix.size(), suffix) == 0 &&
      (first + 1 + suffix.size() == name.size() || name[first + 1 + suffix.size()] == '/'))
    return name;
  return suffix + "/" + name;
}

void appendFlat(Json& flat, const Json& benchmarks, const std::string& suffix) {
  if (!benchmarks.is_array()) return;
  for (Json entry : benchmarks) {
    if (!entry.is_object()) continue;
    for (const char* key : {"name", "run_name"})
      if (entry.contains(key) && entry[key].is_string())
        entry[key] = flatName(entry[key].get<std::string>(), suffix);
    flat.push_back(std::move(entry));
  }
}

// Google Benchmark's own context keys (json_reporter.cc); the others are the
// lines a process adds.
bool isStandardContextKey(const std::string& key) {
  static const char* const keys[] = {"date",     "host_name",          "executable",
                                     "num_cpus", "mhz_per_cpu",        "cpu_scaling_enabled",
                                     "caches",   "load_avg",           "library_build_type",
                                     "json_schema_version"};
  for (const char* k : keys)
    if (key == k) return true;
  return false;
}

// The top-level `context`, in the shape Google Benchmark writes, for its
// tools (tools/compare.py): the standard keys of the first process that
// wrote a context (the CPU preparation, else the first backend), then every
// process's own lines, a backend's under "<suffix>." unless they already are.
Json flatContext(const Json& prepare, const Json& backends) {
  std::vector<std::pair<std::string, const Json*>> sources;  // (prefix, context)
  if (prepare.is_object() && prepare.contains("context") && prepare["context"].is_object())
    sources.emplace_back("", &prepare["context"]);
  for (const Json& b : backends)
    if (b.contains("context") && b["context"].is_object() && !b["context"].empty())
      sources.emplace_back(b.value("backend", ""), &b["context"]);
  Json context = Json::object();
  for (const auto& [prefix, source] : sources) {
    if (source->empty()) continue;
    for (auto it = source->begin(); it != source->end(); ++it)
      if (isStandardContextKey(it.key())) context[it.key()] = it.value();
    break;
  }
  for (const auto& [prefix, source] : sources)
    for (auto it = source->begin(); it != source->end(); ++it) {
      if (isStandardContextKey(it.key())) continue;
      const std::string key =
          prefix.empty() || it.key().rfind(prefix + ".", 0) == 0 ? it.key() : prefix + "." + it.key();
      if (!context.contains(key)) context[key] = it.value();
    }
  return context;
}

// Google Benchmark's top-level "context" and "benchmarks" (every backend's
// entries, then the CPU preparation's), beside the per-backend structure,
// so that Google Benchmark's tools read bench.json as they read its own files.
void addFlatArrays(Json& bench) {
  Json flat = Json::array();
  for (const Json& b : bench["backends"])
    appendFlat(flat, b.value("benchmarks", Json::array()), b.value("backend", ""));
  if (bench["prepare"].is_object()) appendFlat(flat, bench["prepare"].value("benchmarks", Json::array()), "cpu");
  bench["context"] = flatContext(bench["prepare"], bench["backends"]);
  bench["benchmarks"] = std::move(flat);
}

// One run of the peak-rate kernel (`lightcts bench-worker peak`) into
// raw/<name>.json; null when it failed (said on `err`).
Json calibratePeak(const BenchOptions& options, const fs::path& rawDir, const std::string& name, std::ostream& out,
                   std::ostream& err) {
  out << "bench: calibrating the peak rate (" << name << ")" << std::endl;
  const ProcessOutcome run = runBenchProcess(options, {"peak"}, rawDir / (name + ".json"), rawDir / (name + ".log"));
  if (run.ok && run.output.contains("peak") && run.output["peak"].contains("gflops")) {
    out << "bench: " << name << " " << run.output["peak"]["gflops"].get<double>() << " GFLOP/s" << std::endl;
    return run.output["peak"];
  }
  err << "lightcts: bench: the peak-rate calibration (" << name << ") failed (" << run.how << ")\n";
  return nullptr;
}

// bench.json's "peak_drift" (docs/bench-format.md): the two calibrations
// compared by reports::peakDrift, which the pages flag; null without both.
Json peakDriftJson(const Json& before, const Json& after) {
  const auto rate = [](const Json& peak) -> std::optional<double> {
    if (!peak.is_object() || !peak.contains("gflops") || !peak["gflops"].is_number()) return std::nullopt;
    return peak["gflops"].get<double>();
  };
  const std::optional<reports::PeakDrift> drift = reports::peakDrift(rate(before), rate(after));
  if (!drift) return nullptr;
  return {{"ratio", *rate(after) / *rate(before)},
          {"difference", drift->difference},
          {"limit", reports::kPeakDriftLimit},
          {"flagged", drift->flagged}};
}

// What one frame-benchmark process of a combination left: its bench.json
// entry and whether it failed.
struct BackendRun {
  Json entry;
  bool ran = false, failed = false;
  std::string summary;  // the line said on `out` when it ends
};

BackendRun runBackend(const BenchOptions& options, const BackendCombination& c, const fs::path& rawDir,
                      const std::vector<std::string>& common) {
  const auto start = Clock::now();
  std::vector<std::string> args = {"frame", "--backend=" + c.backend, "--scenes=" + options.scenesDir};
  if (!c.driver.empty()) args.push_back("--driver=" + c.driver);
  args.insert(args.end(), common.begin(), common.end());
  const ProcessOutcome run = runBenchProcess(options, args, rawDir / (c.suffix + ".json"), rawDir / (c.suffix + ".log"));
  const Json benchmarks = run.output.is_object() ? run.output.value("benchmarks", Json::array()) : Json::array();
  const Json context = run.output.is_object() ? run.output.value("context", Json::object()) : Json::object();
  comparison::BackendStatus status = comparison::BackendStatus::Ran;
  std::string message;
  BackendRun result;
  // Exit 3 (or nothing measured): the backend or driver is not here.
  if (run.exitStatus == 3 || (run.ok && benchmarks.empty())) {
    status = comparison::BackendStatus::NotSupported;
    std::ifstream log(rawDir / (c.suffix + ".log"));
    std::getline(log, message);
  } else if (!run.ok) {
    status = comparison::BackendStatus::Error;
    message = "the benchmark process ended with " + run.how + "; see raw/" + c.suffix + ".log";
    result.failed = true;
  }
  result.ran = status == comparison::BackendStatus::Ran;
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  std::ostringstream line;
  line << "bench: " << c.suffix << ": " << status << (message.empty() ? "" : " (" + message + ")") << ", "
       << benchmarks.size() << " entries, " << std::fixed << std::setprecision(1) << seconds << " s";
  result.summary = line.str();
  result.entry = {{"backend", c.suffix},
                  {"status", comparison::backendStatusName(status)},
                  {"message", message},
                  {"device", deviceFromContext(context, c.suffix)},
                  {"wall_s", seconds},
                  {"context", context},
                  {"benchmarks", benchmarks}};
  return result;
}

}  // namespace

int runBench(const BenchOptions& options, std::ostream& out, std::ostream& err) {
  const auto started = Clock::now();
  const std::string startedUtc = utcTimestamp();
  const std::vector<BackendCombination> combinations = selectCombinations(options.backends);
  if (options.timeoutSeconds <= 0) throw std::invalid_argument("--timeout must be positive");
  std::error_code ec;
  if (!fs::is_directory(options.scenesDir, ec))
    throw std::invalid_argument("--scenes " + options.scenesDir + " is not a folder");
  const fs::path outDir(options.outDir);
  const fs::path rawDir = outDir / "raw";
  fs::create_directories(rawDir);
  const std::vector<std::string> quick = options.quick ? std::vector<std::string>{"--quick"} : std::vector<std::string>{};

  // The calibration first, on a quiet machine: every later limit depends on
  // it. It runs again after the timed runs: a machine loaded
  // during the run shows as a difference between the two, which the pages flag.
  const Json peak = calibratePeak(options, rawDir, "peak", out, err);
  std::vector<std::string> common;  // what every frame process gets
  if (!peak.is_null()) {
    std::ostringstream text;
    text << std::setprecision(17) << peak["gflops"].get<double>();
    common.push_back("--peak_gflops=" + text.str());
  } else {
    err << "lightcts: bench: no physical limit without the peak rate\n";
  }
  common.insert(common.end(), quick.begin(), quick.end());
  // Each frame process picks its set by its driver's measured speed
  // (suite/bench/driver_speed.h) unless told otherwise.
  if (options.fullSet) common.push_back("--set=full");
  // The ideal references (untimed) are the same for every combination's
  // scenes: the first process to need one renders it, the others read it.
  // Their files are keyed by name, not by the code that made them, so they
  // are this run's alone: an earlier run's in the same folder go first.
  const fs::path idealDir = rawDir / "ideal";
  fs::remove_all(idealDir);
  common.push_back("--ideal_cache=" + idealDir.string());
  // The errors, by content and the code's fingerprint, are every run's.
  if (!options.errorCache.empty()) common.push_back("--error_cache=" + fs::absolute(options.errorCache).string());

  std::vector<std::string> prepareArgs = {"prepare"};
  prepareArgs.insert(prepareArgs.end(), quick.begin(), quick.end());
  const auto runPrepare = [&] {
    return runBenchProcess(options, prepareArgs, rawDir / "prepare.json", rawDir / "prepare.log");
  };

  ProcessOutcome prepareRun;
  std::vector<BackendRun> runs;
  if (options.quick) {
    // --quick proves that every mode runs, it measures nothing: the CPU
    // preparation and every combination run at once, so the smoke run takes
    // the slowest process's time, not their sum.
    out << "bench: CPU preparation and " << combinations.size() << " combinations at once (--quick)" << std::endl;
    auto prepareJob = std::async(std::launch::async, runPrepare);
    std::vector<std::future<BackendRun>> jobs;
    for (const BackendCombination& c : combinations)
      jobs.push_back(std::async(std::launch::async, [&, c] { return runBackend(options, c, rawDir, common); }));
    for (auto& job : jobs) runs.push_back(job.get());
    prepareRun = prepareJob.get();
  } else {
    // Timed runs one after the other: two processes at once on the same
    // cores would time each other.
    out << "bench: CPU preparation" << std::endl;
    prepareRun = runPrepare();
    for (const BackendCombination& c : combinations) {
      out << "bench: " << c.suffix << std::endl;
      runs.push_back(runBackend(options, c, rawDir, common));
      out << runs.back().summary << std::endl;
    }
  }
  if (options.quick)
    for (const BackendRun& r : runs) out << r.summary << std::endl;
  const Json prepare = prepareRun.output.is_object()
                           ? Json{{"context", prepareRun.output.value("context", Json::object())},
                                  {"benchmarks", prepareRun.output.value("benchmarks", Json::array())}}
                           : Json(nullptr);
  bool failed = !prepareRun.ok;
  if (!prepareRun.ok) err << "lightcts: bench: the CPU preparation benchmarks failed (" << prepareRun.how << ")\n";
  Json backends = Json::array();
  bool anyRan = false;
  for (BackendRun& r : runs) {
    anyRan = anyRan || r.ran;
    failed = failed || r.failed;
    backends.push_back(std::move(r.entry));
  }
  const Json peakAfter = calibratePeak(options, rawDir, "peak_after", out, err);
  const Json drift = peakDriftJson(peak, peakAfter);
  if (drift.is_object() && drift["flagged"].get<bool>())
    err << "lightcts: bench: the peak rate changed by " << std::fixed << std::setprecision(0)
        << 100 * drift["difference"].get<double>() << std::defaultfloat
        << "% during the run (a loaded machine); the pages flag it\n";

  Json bench = {{"format", "lightcts-bench"},
                {"version", 1},
                {"lightcts_revision", revision()},
                {"started_utc", startedUtc},
                {"duration_s", std::chrono::duration<double>(Clock::now() - started).count()},
                {"command", options.commandLine},
                {"quick", options.quick},  // a smoke test, not a measurement
                {"machine", thisMachine().toJson()},
                {"peak", peak},
                {"peak_after", peakAfter},
                {"peak_drift", drift},
                {"backends", backends},
                {"prepare", prepare}};
  addFlatArrays(bench);
  reports::writeBenchReport(bench, outDir);
  imaging::writeFileAtomically(outDir / "bench.json", bench.dump(1) + "\n");
  out << "bench: " << (outDir / "bench.json").string() << ", pages in " << (outDir / "index.html").string() << std::endl;
  if (!anyRan && !failed) {
    err << "lightcts: bench: no backend asked for is present here (NotSupported)\n";
    return 3;
  }
  return failed ? 4 : 0;
}

}  // namespace runner
