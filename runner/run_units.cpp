#include "runner/run_units.h"

#include "conformance/scene_lists.h"

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

bool isWitness(shaders::Admissible variant, const std::string& caseName) {
  const std::vector<std::string>* witnesses =
      conformance::witnessesOf(std::string(shaders::admissibleName(variant)));
  return witnesses && std::find(witnesses->begin(), witnesses->end(), caseName) != witnesses->end();
}

std::string killerList(shaders::Mutant mutant) {
  const std::vector<std::string>* killers = conformance::killersOf(std::string(shaders::mutantName(mutant)));
  std::string text;
  if (killers)
    for (const std::string& killer : *killers) text += (text.empty() ? "" : ", ") + killer;
  return text.empty() ? "none in suite/mutant_killers.def" : text;
}

// The admissible variants' tests of one scene on one combination: one per
// variant asked for that the combination's API realises.
std::vector<std::string> admissibleTests(const RunInputs& inputs, const std::string& caseName,
                                         const BackendCombination& combination) {
  std::vector<std::string> names;
  for (const shaders::Admissible variant : inputs.askedAdmissible)
    if (shaders::admissibleRealisedOn(variant, combination.backend))
      names.push_back(admissibleTestName(caseName, variant, combination.suffix));
  return names;
}

// Every selected test with its tasks: the model's (unless --mutants-only or
// --admissible-only), then one per mutant this scene is to be checked
// against (its killers, or every scene with --mutants-all-scenes), then one
// test per admissible variant asked for. The selection chooses among the
// model's and the variants' test names alike; a mutant goes with the model's
// test. Decided once before sharding: the shards of a selection partition
// exactly the selection.
std::vector<RunUnit> allUnits(const RunOptions& options, const RunInputs& inputs,
                              std::set<shaders::Mutant>& checkedMutants) {
  std::vector<std::string> testNames;
  for (const BackendCombination& combination : inputs.combinations)
    for (const CatalogueEntry& scene : inputs.catalogue) {
      testNames.push_back(scene.file.caseName() + "." + combination.suffix);
      for (std::string& name : admissibleTests(inputs, scene.file.caseName(), combination))
        testNames.push_back(std::move(name));
    }
  const std::vector<bool> selected = inputs.selection.select(testNames);
  std::vector<RunUnit> units;
  std::size_t t = 0;
  for (std::size_t c = 0; c < inputs.combinations.size(); ++c)
    for (const CatalogueEntry& scene : inputs.catalogue) {
      const std::string test = scene.file.caseName() + "." + inputs.combinations[c].suffix;
      const std::string path = scene.file.path.string();
      RunUnit unit{c, test, {}};
      if (selected[t++]) {
        if (!options.mutantsOnly && !options.admissibleOnly) unit.tasks.push_back({test, path});
        for (const shaders::Mutant mutant : inputs.askedMutants)
          if (options.mutantsAllScenes || isKiller(mutant, scene.file.caseName())) {
            unit.tasks.push_back({test, path, mutant});
            checkedMutants.insert(mutant);
          }
      }
      for (const shaders::Admissible variant : inputs.askedAdmissible) {
        if (!shaders::admissibleRealisedOn(variant, inputs.combinations[c].backend)) continue;
        if (options.admissibleWitnesses && !isWitness(variant, scene.file.caseName())) {
          ++t;
          continue;
        }
        const std::string name = admissibleTestName(scene.file.caseName(), variant, inputs.combinations[c].suffix);
        if (selected[t++]) unit.tasks.push_back({name, path, shaders::Mutant::None, variant});
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
    plan.mutantsNotChecked.push_back({name, why});
  }
  if (units.empty()) throw std::invalid_argument("nothing to run: the selection holds no killer of any mutant");
  if (!plan.mutantsNotChecked.empty())
    notes << "run: " << plan.mutantsNotChecked.size() << " mutant(s) not checked: the selected scenes hold none of "
          << "their killers (results.json: mutants_not_checked)" << std::endl;
  for (const RunUnit& unit : units)
    plan.testsInRun += std::size_t(std::count_if(unit.tasks.begin(), unit.tasks.end(),
                                                 [](const WorkerTask& task) { return !task.isMutantTask(); }));
  if (options.shard) {
    const std::vector<int> shardOf = assignShards(unitCosts(units, inputs.timings), options.shard->total);
    for (std::size_t u = 0; u < units.size(); ++u)
      if (shardOf[u] == options.shard->index - 1) plan.units.push_back(units[u]);
    plan.shard = results::ShardRecord{options.shard->index,
                                      options.shard->total,
                                      partitionDigest(units, shardOf, options.shard->total),
                                      inputs.timings ? "timings" : "test count",
                                      options.timingsFile,
                                      (long long)plan.testsInRun,
                                      (long long)plan.units.size(),
                                      (long long)units.size()};
  } else {
    plan.units = std::move(units);
  }
  for (const RunUnit& unit : plan.units)
    for (const WorkerTask& task : unit.tasks)
      if (task.isMutantTask()) plan.mutantChecks.emplace(task.mutant, unit.combination);
  return plan;
}

void listRunUnits(const RunUnits& plan, std::ostream& out, std::ostream& err) {
  std::size_t tests = 0, mutantTasks = 0;
  for (const RunUnit& unit : plan.units) {
    // The scene's test names it even when only its mutation check runs.
    const bool modelListed = std::none_of(unit.tasks.begin(), unit.tasks.end(),
                                          [](const WorkerTask& task) { return !task.isMutantTask(); });
    if (modelListed) {
      out << unit.test << "\n";
      ++tests;
    }
    for (const WorkerTask& task : unit.tasks) {
      if (task.isMutantTask()) {
        ++mutantTasks;
        continue;
      }
      out << task.test << "\n";
      ++tests;
    }
  }
  err << "run: " << tests << " test(s), " << mutantTasks << " mutation-check task(s)" << std::endl;
}

}  // namespace runner
