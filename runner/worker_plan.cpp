#include "runner/worker_plan.h"

#include <optional>
#include <stdexcept>

namespace runner {

nlohmann::json planToJson(const WorkerPlan& plan) {
  nlohmann::json tasks = nlohmann::json::array();
  for (const WorkerTask& t : plan.tasks)
    tasks.push_back({{"test", t.test},
                     {"scene", t.scene},
                     {"mutant", shaders::mutantName(t.mutant)},
                     {"admissible", shaders::admissibleName(t.admissible)}});
  return {{"suffix", plan.combination.suffix},
          {"backend", plan.combination.backend},
          {"driver", plan.combination.driver},
          {"device", plan.device},
          {"expect_driver", plan.expectDriver},
          {"out_dir", plan.outDir},
          {"reference_cache", plan.referenceCache},
          {"measure_sharpness", plan.measureSharpness},
          {"tasks", tasks}};
}

WorkerPlan planFromJson(const nlohmann::json& json) {
  WorkerPlan plan;
  plan.combination = {json.at("suffix").get<std::string>(), json.at("backend").get<std::string>(),
                      json.at("driver").get<std::string>()};
  plan.device = json.at("device").get<std::string>();
  plan.expectDriver = json.at("expect_driver").get<std::string>();
  plan.outDir = json.at("out_dir").get<std::string>();
  plan.referenceCache = json.value("reference_cache", "");
  plan.measureSharpness = json.value("measure_sharpness", false);
  for (const auto& t : json.at("tasks")) {
    const std::string mutant = t.at("mutant").get<std::string>();
    const std::optional<shaders::Mutant> known = shaders::mutantFromName(mutant);
    if (!known) throw std::invalid_argument("unknown mutant '" + mutant + "'");
    const std::string admissible = t.value("admissible", "none");
    const std::optional<shaders::Admissible> variant = shaders::admissibleFromName(admissible);
    if (!variant) throw std::invalid_argument("unknown admissible variant '" + admissible + "'");
    plan.tasks.push_back({t.at("test").get<std::string>(), t.at("scene").get<std::string>(), *known, *variant});
  }
  return plan;
}

std::string admissibleTestName(const std::string& caseName, shaders::Admissible variant, const std::string& suffix) {
  return caseName + "@" + std::string(shaders::admissibleName(variant)) + "." + suffix;
}

std::string caseOfTest(const std::string& test) {
  const std::string withoutSuffix = test.substr(0, test.rfind('.'));
  return withoutSuffix.substr(0, withoutSuffix.find('@'));
}

std::string testEvidenceDir(const std::string& test) { return "evidence/" + test; }

std::string mutantEvidenceDir(shaders::Mutant mutant, const std::string& suffix) {
  return "mutants/" + std::string(shaders::mutantName(mutant)) + "." + suffix;
}

}  // namespace runner
