#include "runner/suite_worker.h"

#include "app/exit_status.h"
#include "backends/expected_driver.h"
#include "baking/bake.h"
#include "comparison/comparison_report.h"
#include "comparison/verdict.h"
#include "conformance/scene_check.h"
#include "results/run_records.h"
#include "runner/worker_protocol.h"
#include "scene_input/scene_loader.h"

#include <csignal>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <unistd.h>

namespace runner {
namespace {

using Json = nlohmann::ordered_json;
namespace fs = std::filesystem;


results::DeviceRecord deviceRecord(const backends::DeviceInfo& d) {
  // What the device promises, which the tolerances use (docs/tolerances.md).
  return {d.name, d.driver, d.driverVersion, d.apiVersion, d.selectedBy, d.subPixelPrecisionBits,
          d.subTexelPrecisionBits};
}

void emit(std::ostream& out, const Json& line) { out << line.dump() << '\n' << std::flush; }

// Test-only hooks (docs/cli.md): make the worker die or hang at one test, so
// the runner's Crash and Timeout handling is tested against a real process.
void testHooks(const std::string& test) {
  if (const char* crash = std::getenv("LIGHTCTS_TEST_CRASH_ON"); crash && test == crash) std::raise(SIGSEGV);
  if (const char* hang = std::getenv("LIGHTCTS_TEST_HANG_ON"); hang && test == hang)
    for (;;) pause();
  // TEST:MARKER: crash at TEST only while MARKER does not exist, creating it
  // first, so the test's first attempt crashes and its retry passes (a Flake).
  if (const char* once = std::getenv("LIGHTCTS_TEST_CRASH_ONCE")) {
    const std::string spec = once;
    const std::size_t colon = spec.find(':');
    if (colon != std::string::npos && test == spec.substr(0, colon)) {
      const fs::path marker = spec.substr(colon + 1);
      if (!fs::exists(marker)) {
        std::ofstream(marker) << "crashed once at " << test << "\n";
        std::raise(SIGSEGV);
      }
    }
  }
}

// Metrics over every frame checked: counts summed, errors and tightness the
// largest; the worst pixels are those of the evidence frame.
results::Metrics metricsOf(const conformance::SceneCheck& check) {
  results::Metrics m;
  double maxAbs = 0, tightness = 0, rmse = 0;
  for (const conformance::FrameCheck& f : check.frames) {
    const comparison::Comparison& c = f.comparison;
    m.comparedPixels += c.comparedPixels;
    m.maskedPixels += c.maskedPixels;
    m.litComparedPixels += c.litComparedPixels;
    m.failingPixels += c.failingPixels;
    m.nonFinitePixels += c.nonFinitePixels;
    maxAbs = std::max(maxAbs, c.maxAbsError);
    tightness = std::max(tightness, c.maxErrorOverTolerance);
    rmse = std::max(rmse, c.rmse);
  }
  const comparison::Comparison& e = check.evidence().comparison;
  for (const comparison::PixelReport& p : e.worst) {
    results::WorstPixel pixel;
    pixel.x = p.x;
    pixel.y = p.y;
    for (int c = 0; c < 3; ++c) {
      pixel.result[std::size_t(c)] = results::measuredOf(p.result[c]);
      pixel.reference[std::size_t(c)] = results::measuredOf(p.reference[c]);
      pixel.tolerance[std::size_t(c)] = results::measuredOf(p.tolerance[c]);
    }
    pixel.toleranceScale = e.toleranceScale;
    m.worst.push_back(pixel);
  }
  m.maxFailingPixels = e.maxFailingPixels;
  m.maxAbsError = results::measuredOf(maxAbs);
  m.rmse = results::measuredOf(rmse);
  m.tightness = results::measuredOf(tightness);
  m.tightnessIsInfinite = std::isinf(tightness);
  m.expectFail = e.expectFail;
  return m;
}

std::vector<results::FrameRecord> framesOf(const conformance::SceneCheck& check) {
  std::vector<results::FrameRecord> frames;
  for (const conformance::FrameCheck& f : check.frames)
    frames.push_back({f.frame, f.comparison.verdict, f.comparison.failingPixels, results::measuredOf(f.comparison.maxAbsError),
                      results::measuredOf(f.comparison.maxErrorOverTolerance), results::measuredOf(f.idealError),
                      results::measuredOf(f.poppingJump)});
  return frames;
}

class Worker {
 public:
  Worker(const WorkerPlan& plan, std::ostream& out) : plan_(plan), out_(out) {}

  int run(int start) {
    for (int i = start; i < int(plan_.tasks.size()); ++i) {
      const WorkerTask& task = plan_.tasks[std::size_t(i)];
      if (int status = ensureBackend(task); status != 0) return status;
      testHooks(task.test);
      results::TaskResult result;
      result.test = task.test;
      try {
        runTask(task, result);
      } catch (const backends::NotSupportedError& e) {
        result.rawVerdict = comparison::Verdict::NotSupported;
        result.message = e.what();
      } catch (const backends::DriverError& e) {
        result.rawVerdict = comparison::Verdict::Crash;
        result.message = std::string("driver error: ") + e.what();
        emitResult(i, result);
        return app::kExitInternalError;
      } catch (const std::exception& e) {
        result.rawVerdict = comparison::Verdict::Crash;
        result.message = std::string("internal error: ") + e.what();
      }
      emitResult(i, result);
    }
    return 0;
  }

 private:
  // The protocol's result line (runner/worker_protocol.h): the task's index in
  // the plan and its result.
  void emitResult(int index, const results::TaskResult& result) {
    emit(out_, protocol::resultLine(std::size_t(index), result));
  }

  // One backend at a time, built for the task's shader variant.
  int ensureBackend(const WorkerTask& task) {
    const shaders::Mutant mutant = task.mutant;
    if (backend_ && task.sameShaders(backendShaders_)) return 0;
    backend_.reset();
    const backends::BackendEntry* entry = backends::findBuiltBackendEntry(plan_.combination.backend);
    try {
      if (!entry) throw backends::NotSupportedError("backend '" + plan_.combination.backend + "' is not built");
      backends::BackendOptions options;
      options.device = plan_.device;
      // With --device, the device decides the GL driver (a vendor's EGL
      // device); the softpipe combinations still ask Mesa for softpipe.
      const bool deviceDecides = !plan_.device.empty() && plan_.combination.driver == "llvmpipe";
      options.driver = deviceDecides ? "" : plan_.combination.driver;
      options.validation = backends::validationRequestedByDefault();
      // Test hook: this mutant's backend fails to build, as a driver that
      // cannot compile one shader variant would (runner/part_run.cpp).
      const std::string name(shaders::mutantName(mutant));
      if (const char* broken = std::getenv("LIGHTCTS_TEST_BACKEND_ERROR_FOR_MUTANT"); broken && name == broken)
        throw std::runtime_error("test hook: mutant " + name + "'s backend does not build");
      options.variant.mutant = mutant;
      options.variant.admissible = task.admissible;
      backend_ = entry->create(options);
      const backends::DeviceInfo device = backend_->device();
      backends::requireExpectedDriver(device, plan_.expectDriver);
      backendShaders_ = task;
      if (!announced_)
        emit(out_, {{protocol::kKind, protocol::kDevice}, {protocol::kDeviceField, deviceRecord(device).toJson()}});
      announced_ = true;
      return 0;
    } catch (const backends::NotSupportedError& e) {
      emit(out_, {{protocol::kKind, protocol::kBackendUnavailable}, {protocol::kMessage, e.what()}});
      return app::kExitNotSupported;
    } catch (const std::exception& e) {
      emit(out_, {{protocol::kKind, protocol::kBackendError}, {protocol::kMessage, e.what()}});
      return app::kExitInternalError;
    }
  }

  conformance::SceneReferences& referencesOf(const std::string& scene) {
    auto it = references_.find(scene);
    if (it == references_.end()) {
      auto prepared = baking::prepareBakedScene(scene_input::loadSceneFile(scene));
      auto caching = conformance::referenceCaching(plan_.referenceCache, scene, prepared->scene);
      it = references_.emplace(scene, std::make_unique<conformance::SceneReferences>(std::move(prepared), caching))
               .first;
    }
    return *it->second;
  }

  void runTask(const WorkerTask& task, results::TaskResult& result) {
    conformance::SceneReferences& references = referencesOf(task.scene);
    conformance::CheckOptions options;
    options.mutant = task.mutant;
    options.measureSharpness = plan_.measureSharpness && task.isModelTest();
    const conformance::SceneCheck check = conformance::checkScene(references, *backend_, options);
    result.rawVerdict = check.verdict;
    result.message = check.qualityWarning;  // why a QualityWarning checks nothing; "" otherwise
    result.metrics = metricsOf(check);
    if (check.caughtScale)  // docs/results-format.md: the smallest relative brightness errors caught
      result.metrics->caught =
          results::CaughtBrightness{results::measuredOf(check.caughtScale->brighter), results::measuredOf(check.caughtScale->darker)};
    result.frames = framesOf(check);
    result.poppingScore = check.poppingScore ? results::measuredOf(*check.poppingScore) : std::nullopt;
    const conformance::StageTimings& t = check.timings;
    result.timingsMs = results::StageTimes{t.reference, t.pipeline, t.draw, t.readback, t.compare, t.total};
    result.evidence = std::nullopt;
    // Every failing test leaves evidence; a mutant leaves it for its first
    // kill; an expect_fail scene whose known mismatch was detected leaves it
    // too, so the report shows how far off that mismatch is.
    const bool isMutant = task.isMutantTask();
    const bool detectedMismatch = !isMutant && references.prepared()->scene.expect.expectFail;
    if (check.verdict != comparison::Verdict::Fail && !detectedMismatch) return;
    if (isMutant && !evidencedMutants_.insert(task.mutant).second) return;
    const std::string dir =
        isMutant ? mutantEvidenceDir(task.mutant, plan_.combination.suffix) : testEvidenceDir(task.test);
    comparison::writeEvidence((fs::path(plan_.outDir) / dir).string(), check.evidence().comparison,
                              check.evidenceResult, check.evidenceReference, task.test, &check.evidenceShadowMaps);
    result.evidence = results::EvidenceRecord::inFolder(dir, check.evidenceFrame);
  }

  const WorkerPlan& plan_;
  std::ostream& out_;
  std::unique_ptr<backends::Backend> backend_;
  WorkerTask backendShaders_;  // the shader variant backend_ was built for
  bool announced_ = false;
  std::map<std::string, std::unique_ptr<conformance::SceneReferences>> references_;
  std::set<shaders::Mutant> evidencedMutants_;
};

}  // namespace

int runWorker(const WorkerPlan& plan, int start, std::ostream& out) { return Worker(plan, out).run(start); }

}  // namespace runner
