// A stand-in for `lightcts worker` that runs no driver: it speaks the worker
// protocol (runner/worker_protocol.h) from a script, so that the runner's
// part runs, retries, timeouts, shards and interruptions are tested on a
// machine without Vulkan or GL. Called as the runner calls a worker:
//   mock_worker worker --plan FILE --start N
// The script is the JSON file LIGHTCTS_MOCK_SCRIPT names:
//   {"start": "up",                      every worker's start (below)
//    "tests": {"<test>": ["crash", "pass"]},   a test's events, one per attempt
//                                              (the last repeats); others pass
//    "devices": {"vulkan": {...}}}       the device line per combination suffix
// Start: "up" | "absent" (backend_unavailable) | "crash" | "hang" | "slow:MS".
// Events: "pass" | "fail" | "crash" (SIGKILL) | "hang" | "garbage" (lines
// that are no protocol object, then a pass) | "pass-then-exit-4" (a driver
// error after the result) | "backend-error" | "interrupt:SIGINT" |
// "interrupt:SIGTERM" (signals the runner, then hangs) | "interrupt-and-die:SIGINT"
// (signals the runner, then dies of that signal) | "interrupt-and-chatter:SIGINT"
// (signals the runner, then writes lines without end) | "signalled:SIGTERM"
// (dies of that signal, the runner not signalled).
// Each attempt is counted in <plan outDir>/mock-attempts.txt, each worker
// start in mock-starts.txt.
#include "app/exit_status.h"
#include "results/run_records.h"
#include "runner/worker_plan.h"
#include "runner/worker_protocol.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <thread>
#include <unistd.h>

namespace {

using Json = nlohmann::ordered_json;
namespace fs = std::filesystem;
namespace protocol = runner::protocol;

void emit(const Json& line) { std::cout << line.dump() << '\n' << std::flush; }

[[noreturn]] void hang() {
  for (;;) pause();
}

[[noreturn]] void crash() {
  std::raise(SIGKILL);
  hang();
}

// Appends `what` to `file` and says how often it was there before.
int countBefore(const fs::path& file, const std::string& what) {
  int seen = 0;
  {
    std::ifstream in(file);
    for (std::string line; std::getline(in, line);) seen += line == what;
  }
  std::ofstream(file, std::ios::app) << what << '\n';
  return seen;
}

std::string eventOf(const Json& script, const std::string& test, int attempt) {
  const Json tests = script.value("tests", Json::object());
  const auto it = tests.find(test);
  if (it == tests.end() || !it->is_array() || it->empty()) return "pass";
  return (*it)[std::min<std::size_t>(std::size_t(attempt), it->size() - 1)].get<std::string>();
}

int signalOf(const std::string& event) { return event.ends_with("SIGTERM") ? SIGTERM : SIGINT; }

void emitResult(std::size_t index, const std::string& test, comparison::Verdict verdict) {
  results::TaskResult result;
  result.test = test;
  result.rawVerdict = verdict;
  result.metrics = results::Metrics{};
  result.metrics->comparedPixels = 16;
  result.metrics->failingPixels = verdict == comparison::Verdict::Fail ? 3 : 0;
  result.timingsMs = results::StageTimes{1.0, 1.0, 1.0, 1.0, 1.0, 5.0 + double(index)};
  emit(protocol::resultLine(index, result));
}

}  // namespace

int main(int argc, char** argv) {
  std::string planFile;
  std::size_t start = 0;
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::string(argv[i]) == "--plan") planFile = argv[i + 1];
    if (std::string(argv[i]) == "--start") start = std::stoul(argv[i + 1]);
  }
  const char* scriptFile = std::getenv("LIGHTCTS_MOCK_SCRIPT");
  if (planFile.empty() || !scriptFile) {
    std::cerr << "mock_worker: needs --plan FILE and LIGHTCTS_MOCK_SCRIPT\n";
    return app::kExitBadInput;
  }
  const runner::WorkerPlan plan = runner::planFromJson(Json::parse(std::ifstream(planFile)));
  const Json script = Json::parse(std::ifstream(scriptFile));
  const fs::path outDir = plan.outDir;
  countBefore(outDir / "mock-starts.txt", plan.combination.suffix);

  const std::string startEvent = script.value("start", "up");
  if (startEvent == "crash") crash();
  if (startEvent == "hang") hang();
  if (startEvent == "absent") {
    emit({{protocol::kKind, protocol::kBackendUnavailable}, {protocol::kMessage, "mock: no such driver here"}});
    return app::kExitNotSupported;
  }
  if (startEvent.starts_with("slow:"))
    std::this_thread::sleep_for(std::chrono::milliseconds(std::stoi(startEvent.substr(5))));
  const Json devices = script.value("devices", Json::object());
  emit({{protocol::kKind, protocol::kDevice},
        {protocol::kDeviceField, devices.value(plan.combination.suffix, Json{{"name", "mock device"}})}});

  for (std::size_t index = start; index < plan.tasks.size(); ++index) {
    const std::string& test = plan.tasks[index].test;
    const std::string event = eventOf(script, test, countBefore(outDir / "mock-attempts.txt", test));
    if (event == "crash") crash();
    if (event == "hang") hang();
    if (event.starts_with("interrupt:")) {
      kill(getppid(), signalOf(event));
      hang();
    }
    if (event.starts_with("interrupt-and-die:")) {  // the same signal reaches the worker, and ends it
      kill(getppid(), signalOf(event));
      signal(signalOf(event), SIG_DFL);
      std::raise(signalOf(event));
      hang();
    }
    if (event.starts_with("signalled:")) {  // ended by a signal someone sent the worker alone
      signal(signalOf(event), SIG_DFL);
      std::raise(signalOf(event));
      hang();
    }
    if (event.starts_with("interrupt-and-chatter:")) {  // a worker that never stops writing
      kill(getppid(), signalOf(event));
      for (;;) std::cout << "a driver's line\n" << std::flush;
    }
    if (event == "backend-error") {
      emit({{protocol::kKind, protocol::kBackendError}, {protocol::kMessage, "mock: the driver broke"}});
      return app::kExitInternalError;
    }
    if (event == "garbage") {
      std::cout << "a driver's own line\n42\n[1, 2]\n{\"kind\": \"unheard-of\"}\n" << std::flush;
      emit({{protocol::kKind, protocol::kResult}, {protocol::kIndex, index + 1}, {"test", "out of turn"}});
    }
    emitResult(index, test, event == "fail" ? comparison::Verdict::Fail : comparison::Verdict::Pass);
    if (event == "pass-then-exit-4") return app::kExitInternalError;
  }
  return app::kExitSuccess;
}
