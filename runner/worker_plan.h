// What `lightcts run` hands a worker process (`lightcts worker`): one backend
// combination and the tests to run on it, in order. Tests are grouped by
// mutant (the model first), because a backend is built for one shader variant
// and a worker keeps one backend at a time.
#pragma once

#include "runner/backend_combination.h"
#include "shaders/shader_variant.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace runner {

struct WorkerTask {
  std::string test;   // <group>.<name>.<suffix>
  std::string scene;  // scene file path
  shaders::Mutant mutant = shaders::Mutant::None;  // None: the model's own test

  bool isModelTest() const { return mutant == shaders::Mutant::None; }
};

struct WorkerPlan {
  BackendCombination combination;
  std::string device;        // --device, "" for the default
  std::string expectDriver;  // --expect-driver, "" for no check
  std::string outDir;        // evidence goes under outDir/evidence and outDir/mutants
  // The reference cache folder (conformance/reference_cache.h) every worker
  // of the run shares; "" for none (`--no-reference-cache`).
  std::string referenceCache;
  std::vector<WorkerTask> tasks;
};

nlohmann::json planToJson(const WorkerPlan& plan);
// Throws nlohmann::json::exception, or std::invalid_argument for a mutant no
// build of lightcts knows.
WorkerPlan planFromJson(const nlohmann::json& json);

// The evidence folders, relative to the run's --out folder.
std::string testEvidenceDir(const std::string& test);                           // evidence/<test>
std::string mutantEvidenceDir(shaders::Mutant mutant, const std::string& suffix);  // mutants/<mutant>.<suffix>

}  // namespace runner
