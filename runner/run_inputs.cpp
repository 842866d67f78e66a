#include "runner/run_inputs.h"

#include "scene_input/scene_loader.h"

#include <algorithm>
#include <iostream>
#include <stdexcept>
#include <thread>

namespace runner {
namespace {

// Every scene is loaded before any worker starts: a scene with a typo stops
// the run with exit 2 and the JSON path, before anything is written.
std::vector<CatalogueEntry> loadCatalogue(const std::string& scenesDir) {
  std::vector<CatalogueEntry> catalogue;
  for (const conformance::SceneFile& file : conformance::findSceneFiles(scenesDir)) {
    const lighting::Scene scene = scene_input::loadSceneFile(file.path.string());
    // An import's warnings (SPEC 2.1), once per run; the workers stay quiet.
    for (const std::string& warning : scene.warnings) std::cerr << "lightcts: warning: " << warning << "\n";
    catalogue.push_back({file, scene.description});
  }
  return catalogue;
}

std::vector<shaders::Mutant> mutantsAskedFor(const RunOptions& options) {
  std::vector<shaders::Mutant> mutants;
  if (options.noMutants || (options.admissibleOnly && options.mutants.empty())) return mutants;
  for (const std::string& name : options.mutants) {
    const std::optional<shaders::Mutant> mutant = shaders::mutantFromName(name);
    if (!mutant || *mutant == shaders::Mutant::None) throw std::invalid_argument("unknown --mutant '" + name + "'");
    mutants.push_back(*mutant);
  }
  if (!options.mutants.empty()) return mutants;
  for (const shaders::MutantName& m : shaders::mutantNames()) mutants.push_back(m.mutant);
  return mutants;
}

// --admissible NAME... or "all": the variants a shader realises somewhere
// (a variant of the table's `none` rows is refused: it cannot run), in the
// table's order, each once.
std::vector<shaders::Admissible> admissibleAskedFor(const RunOptions& options) {
  std::vector<shaders::Admissible> asked;
  const bool all = std::find(options.admissible.begin(), options.admissible.end(), "all") != options.admissible.end();
  for (const std::string& name : options.admissible) {
    if (name == "all") continue;
    const std::optional<shaders::Admissible> variant = shaders::admissibleFromName(name);
    if (!variant || *variant == shaders::Admissible::None)
      throw std::invalid_argument("unknown --admissible '" + name + "'");
    if (shaders::admissibleEntry(*variant).apis == shaders::AdmissibleApis::None)
      throw std::invalid_argument("--admissible " + name + " is not realised by any shader: " +
                                  std::string(shaders::admissibleEntry(*variant).what));
  }
  for (const shaders::AdmissibleName& a : shaders::admissibleNames()) {
    if (a.apis == shaders::AdmissibleApis::None) continue;
    if (all || std::find(options.admissible.begin(), options.admissible.end(), a.name) != options.admissible.end())
      asked.push_back(a.variant);
  }
  return asked;
}

}  // namespace

RunInputs checkRunInputs(const RunOptions& options) {
  RunInputs inputs;
  try {
    inputs.catalogue = loadCatalogue(options.scenesDir);
    for (const std::string& file : options.expectedFailureFiles) inputs.expected.load(file);
  } catch (const std::runtime_error& e) {
    throw std::invalid_argument(e.what());  // a bad scene or baseline is bad input (exit 2)
  }
  inputs.combinations = selectCombinations(options.backends, options.driver);
  for (const std::string& glob : options.includes) inputs.selection.include(glob);
  for (const std::string& glob : options.excludes) inputs.selection.exclude(glob);
  for (const std::string& file : options.caselists) inputs.selection.loadCaselist(file);
  inputs.askedMutants = mutantsAskedFor(options);
  inputs.askedAdmissible = admissibleAskedFor(options);
  if (options.admissibleOnly && inputs.askedAdmissible.empty())
    throw std::invalid_argument("nothing to run: --admissible-only needs --admissible NAME (or all)");
  if (options.admissibleWitnesses && inputs.askedAdmissible.empty())
    throw std::invalid_argument("--admissible-witnesses chooses scenes for the admissible variants: it needs --admissible");
  if (options.admissibleOnly && options.mutantsOnly)
    throw std::invalid_argument("--admissible-only and --mutants-only each run one check alone: choose one");
  if (options.timeoutSeconds <= 0) throw std::invalid_argument("--timeout must be positive");
  if (options.flakeRetries < 0) throw std::invalid_argument("--flake-retries must be 0 or more");
  if (options.jobs < 0) throw std::invalid_argument("--jobs must be 1 or more (0: one per core)");
  if (options.mutantsOnly && inputs.askedMutants.empty())
    throw std::invalid_argument("nothing to run: --mutants-only with --no-mutants");
  if (options.evidenceLimit < 0) throw std::invalid_argument("--evidence-limit must be 0 or more");
  if (options.mutantsAllScenes && options.noMutants)
    throw std::invalid_argument("--mutants-all-scenes checks mutants, and --no-mutants skips them: choose one");
  if (!options.timingsFile.empty() && !options.shard)
    throw std::invalid_argument("--timings balances shards: it needs --shard I/N");
  if (!options.timingsFile.empty()) inputs.timings = loadTimings(options.timingsFile);
  inputs.jobs = options.jobs > 0 ? options.jobs : int(std::max(1u, std::thread::hardware_concurrency()));
  return inputs;
}

}  // namespace runner
