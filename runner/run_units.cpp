#include "runner/run_units.h"

#include "conformance/mutant_killers.h"

#include <algorithm>
#include <ostream>
#include <stdexcept>
#include <string>

namespace runner {
namespace {

using Json = nlohmann::ordered_json;

bool isKiller(shaders::Mutant mutant, const std::string& caseName) {
  const std::vector<std::string>* killers = conformance::killersOf(std::string(shaders::mutantName(mutant)));
  return killers && std::find(killers->begin(), killers->end(), caseName) != killers->end();
}

std::string killerList(shaders::Mutant mutant) {
  const std::vector<std::string>* killers = conformance::killersOf(std::string(shaders::mutantName(mutant)));
  std::string text;
  if (killers)
    for (const std::string& killer : *killers) text += (text.empty() ? "" : ", ") + killer;
  return text.empty() ? "none in suite/mutant_killers.def" : text;
}

// Every selected test with its tasks: the model's (unless --mutants-only),
// then one per mutant this scene is to be checked against (its killers, or
// every scene with --mutants-all-scenes). Decided once before sharding: the
// shards of a selection partition exactly the selection.
std::vector<RunUnit> allUnits(const RunOptions& options, const RunInputs& inputs,
                              std::set<shaders::Mutant>& checkedMutants) {
  std::vector<std::string> testNames;
  for (const BackendCombination& combination : inputs.combinations)
    for (const CatalogueEntry& scene : inputs.catalogue)
      testNames.push_back(scene.file.caseName() + "." + combination.suffix);
  const std::vector<bool> selected = inputs.selection.select(testNames);
  std::vector<RunUnit> units;
  for (std::size_t c = 0, t = 0; c < inputs.combinations.size(); ++c)
    for (const CatalogueEntry& scene : inputs.catalogue) {
      if (!selected[t++]) continue;
      const std::string test = scene.file.caseName() + "." + inputs.combinations[c].suffix;
      RunUnit unit{c, test, {}};
      if (!options.mutantsOnly) unit.tasks.push_back({test, scene.file.path.string(), shaders::Mutant::None});
      for (const shaders::Mutant mutant : inputs.askedMutants)
        if (options.mutantsAllScenes || isKiller(mutant, scene.file.caseName())) {
          unit.tasks.push_back({test, scene.file.path.string(), mutant});
          checkedMutants.insert(mutant);
        }
      if (!unit.tasks.empty()) units.push_back(std::move(unit));
    }
  return units;
}

}  // namespace

RunUnits planRunUnits(const RunOptions& options, const RunInputs& inputs, std::ostream& notes) {
  RunUnits plan;
  std::set<shaders::Mutant> checkedMutants;
  std::vector<RunUnit> units = allUnits(options, inputs, checkedMutants);
  // The mutants checked: those asked for that have a scene to run (a
  // selection may leave out every killer of some). A check left out is
  // said, never silent.
  for (const shaders::Mutant mutant : inputs.askedMutants) {
    if (checkedMutants.count(mutant)) {
      plan.mutants.push_back(mutant);
      continue;
    }
    const std::string name(shaders::mutantName(mutant));
    const std::string why = "none of its killers (" + killerList(mutant) + ") is among the selected scenes of " +
                            options.scenesDir;
    if (!options.mutants.empty())
      throw std::invalid_argument("--mutant " + name + ": " + why + "; select one, or use --mutants-all-scenes");
    plan.mutantsNotChecked.push_back({{"mutant", name}, {"reason", why}});
  }
  if (units.empty()) throw std::invalid_argument("nothing to run: the selection holds no killer of any mutant");
  if (!plan.mutantsNotChecked.empty())
    notes << "run: " << plan.mutantsNotChecked.size() << " mutant(s) not checked: the selected scenes hold none of "
          << "their killers (results.json: mutants_not_checked)" << std::endl;
  plan.testsInRun = options.mutantsOnly ? 0 : units.size();
  if (options.shard) {
    const std::vector<int> shardOf = assignShards(unitCosts(units, inputs.timings), options.shard->total);
    for (std::size_t u = 0; u < units.size(); ++u)
      if (shardOf[u] == options.shard->index - 1) plan.units.push_back(units[u]);
    plan.shard = {{"index", options.shard->index},
                  {"total", options.shard->total},
                  {"partition", partitionDigest(units, shardOf, options.shard->total)},
                  {"balanced_by", inputs.timings ? "timings" : "test count"},
                  {"timings_file", options.timingsFile},
                  {"tests_in_run", plan.testsInRun},
                  {"units", plan.units.size()},
                  {"units_in_run", units.size()}};
  } else {
    plan.units = std::move(units);
  }
  for (const RunUnit& unit : plan.units)
    for (const WorkerTask& task : unit.tasks)
      if (!task.isModelTest()) plan.mutantChecks.emplace(task.mutant, unit.combination);
  return plan;
}

void listRunUnits(const RunUnits& plan, std::ostream& out, std::ostream& err) {
  std::size_t mutantTasks = 0;
  for (const RunUnit& unit : plan.units) {
    out << unit.test << "\n";
    mutantTasks += std::size_t(std::count_if(unit.tasks.begin(), unit.tasks.end(),
                                             [](const WorkerTask& task) { return !task.isModelTest(); }));
  }
  err << "run: " << plan.units.size() << " test(s), " << mutantTasks << " mutation-check task(s)" << std::endl;
}

}  // namespace runner
