#include "app/backend_choice.h"

#include "app/exit_status.h"
#include "app/scene_input.h"
#include "backends/backend_combinations.h"
#include "runner/worker_plan.h"
#include "shaders/shader_variant.h"

#include <algorithm>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>

namespace app {

const backends::BackendEntry* resolveBackend(const std::string& name, std::ostream& err, int& status) {
  const auto& known = backends::specBackendNames();
  if (std::find(known.begin(), known.end(), name) == known.end()) {
    err << "lightcts: unknown backend '" << name << "'; expected one of:";
    for (std::size_t i = 0; i < known.size(); ++i) err << (i == 0 ? " " : ", ") << known[i];
    err << "\n";
    status = kExitBadInput;
    return nullptr;
  }
  const backends::BackendEntry* entry = backends::findBuiltBackendEntry(name);
  if (!entry) {
    err << "lightcts: backend '" << name << "' is not supported by this build (NotSupported)\n";
    status = kExitNotSupported;
  }
  return entry;
}

std::optional<lighting::ClusterGridSpec> clusteredMode(const BackendArguments& args) {
  if (args.mode != lighting::kClusteredModeName) return std::nullopt;
  return args.clusterGrid;
}

void checkModeDraws(const lighting::Frame& frame, const BackendArguments& args) {
  if (!clusteredMode(args)) return;
  if (const auto refusal = lighting::clusteredModeRefusal(frame))
    throw InputError(std::string("--mode ") + lighting::kClusteredModeName + ": " + *refusal);
}

lighting::Frame frameInMode(lighting::Frame frame, const BackendArguments& args) {
  checkModeDraws(frame, args);
  if (const auto grid = clusteredMode(args)) {
    try {
      lighting::useLightClusters(frame, *grid);
    } catch (const std::invalid_argument& e) {  // a grid below 1 (the command line refuses one)
      throw InputError(std::string("--mode ") + lighting::kClusteredModeName + ": " + e.what());
    }
  }
  return frame;
}

backends::BackendOptions backendOptions(const BackendArguments& args) {
  backends::BackendOptions options;
  options.device = args.device;
  options.driver = args.driver;
  options.validation = backends::validationRequestedByDefault();
  options.variant.specialised = !args.fullShader;
  const auto mutant = shaders::mutantFromName(args.mutant);
  if (!mutant) {
    std::string known = "none";
    for (const auto& m : shaders::mutantNames()) known += ", " + std::string(m.name);
    throw InputError("unknown --mutant '" + args.mutant + "'; expected one of: " + known);
  }
  options.variant.mutant = *mutant;
  const auto admissible = shaders::admissibleFromName(args.admissible);
  if (!admissible) {
    std::string known = "none";
    for (const auto& a : shaders::admissibleNames()) known += ", " + std::string(a.name);
    throw InputError("unknown --admissible '" + args.admissible + "'; expected one of: " + known);
  }
  if (!shaders::admissibleRealisedOn(*admissible, args.backend))
    throw backends::NotSupportedError("the admissible variant " + args.admissible + " is not realised on " +
                                      args.backend + ": " + std::string(shaders::admissibleEntry(*admissible).what));
  options.variant.admissible = *admissible;
  return options;
}

std::string caseName(const std::string& scenePath, const BackendArguments& args) {
  const std::filesystem::path path(scenePath);
  // The case ends in the combination's suffix (SPEC 10), from the one table;
  // a driver the table does not know keeps its name in the case, so two
  // such runs never share evidence.
  const std::string suffix = backends::combinationWithDriver(args.backend, args.driver).suffix;
  const std::string scene = path.parent_path().filename().string() + "." + path.stem().string();
  const std::optional<shaders::Admissible> variant = shaders::admissibleFromName(args.admissible);
  if (!variant || *variant == shaders::Admissible::None) return scene + "." + suffix;
  return runner::admissibleTestName(scene, *variant, suffix);
}

}  // namespace app
