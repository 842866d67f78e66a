// The first step of `lightcts run`: everything its options name (the scene
// folder, expected-failures files, caselists, backends, mutants, --timings)
// read and checked before any worker starts or anything is written, so bad
// input stops the run with exit 2 and nothing half-written.
#pragma once

#include "conformance/scene_catalogue.h"
#include "runner/backend_combination.h"
#include "runner/expected_failures.h"
#include "runner/run_plan.h"
#include "runner/suite_run.h"
#include "runner/test_selection.h"
#include "shaders/shader_variant.h"

#include <optional>
#include <string>
#include <vector>

namespace runner {

struct CatalogueEntry {
  conformance::SceneFile file;
  std::string description;
};

struct RunInputs {
  std::vector<CatalogueEntry> catalogue;  // every scene of --scenes, loaded
  ExpectedFailures expected;
  std::vector<BackendCombination> combinations;
  TestSelection selection;
  std::vector<shaders::Mutant> askedMutants;  // --mutant, or every mutant; none with --no-mutants or --admissible-only
  std::vector<shaders::Admissible> askedAdmissible;  // --admissible, in table order
  std::optional<Timings> timings;             // --timings
  int jobs = 1;                               // --jobs, 0 resolved to one per core
};

// Throws std::invalid_argument (exit 2) for a scene that does not load, a
// malformed baseline or caselist, an unknown backend or mutant, or options
// that contradict each other.
RunInputs checkRunInputs(const RunOptions& options);

}  // namespace runner
