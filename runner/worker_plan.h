// What `lightcts run` hands a worker process (`lightcts worker`): one backend
// combination and the tests to run on it, in order. Tests are grouped by
// shader variant (the model first, then each admissible variant and each
// mutant), because a backend is built for one shader variant and a worker
// keeps one backend at a time.
#pragma once

#include "runner/backend_combination.h"
#include "shaders/shader_variant.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace runner {

struct WorkerTask {
  // <group>.<name>.<suffix>; an admissible variant's test is
  // <group>.<name>@<variant>.<suffix> (admissibleTestName).
  std::string test;
  std::string scene;  // scene file path
  shaders::Mutant mutant = shaders::Mutant::None;  // None: a test, the model's or an admissible variant's
  shaders::Admissible admissible = shaders::Admissible::None;  // None: the model's shaders

  // The model's own test: neither a mutation-check task nor a variant's test.
  bool isModelTest() const { return !isMutantTask() && admissible == shaders::Admissible::None; }
  // A mutation-check task: meant to fail, never a test of its own.
  bool isMutantTask() const { return mutant != shaders::Mutant::None; }
  bool sameShaders(const WorkerTask& other) const { return mutant == other.mutant && admissible == other.admissible; }
};

// <group>.<name>@<variant>.<suffix> for the test <group>.<name>.<suffix>.
std::string admissibleTestName(const std::string& caseName, shaders::Admissible variant, const std::string& suffix);

struct WorkerPlan {
  BackendCombination combination;
  std::string device;        // --device, "" for the default
  std::string expectDriver;  // --expect-driver, "" for no check
  std::string outDir;        // evidence goes under outDir/evidence and outDir/mutants
  // The reference cache folder (conformance/reference_cache.h) every worker
  // of the run shares; "" for none (`--no-reference-cache`).
  std::string referenceCache;
  bool measureSharpness = false;  // --sharpness: each model test bisects its smallest caught brightness error
  std::vector<WorkerTask> tasks;
};

nlohmann::json planToJson(const WorkerPlan& plan);
// Throws nlohmann::json::exception, or std::invalid_argument for a mutant no
// build of lightcts knows.
WorkerPlan planFromJson(const nlohmann::json& json);

// The evidence folders, relative to the run's --out folder.
std::string testEvidenceDir(const std::string& test);                           // evidence/<test>
std::string mutantEvidenceDir(shaders::Mutant mutant, const std::string& suffix);  // mutants/<mutant>.<suffix>
// The scene a test name is of: <group>.<name>, without a variant or suffix.
std::string caseOfTest(const std::string& test);

}  // namespace runner
