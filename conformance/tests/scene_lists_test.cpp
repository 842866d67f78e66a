// The scene tables (suite/mutant_killers.def, suite/admissible_witnesses.def)
// against what they name: every mutant the shaders and the CPU model know,
// and every admissible variant a shader realises, has a line; every line
// names a known one once; and every scene named is a scene of suite/scenes.
#include "conformance/scene_catalogue.h"
#include "conformance/scene_lists.h"
#include "shaders/shader_variant.h"

#include <gtest/gtest.h>

#include <set>

namespace conformance {
namespace {

std::set<std::string> suiteCases() {
  std::set<std::string> cases;
  for (const SceneFile& file : findSceneFiles(LIGHTCTS_SCENES_DIR)) cases.insert(file.caseName());
  return cases;
}

TEST(MutantKillers, EveryMutantHasKillers) {
  for (const shaders::MutantName& m : shaders::mutantNames()) {
    if (m.name == "none") continue;
    const std::vector<std::string>* killers = killersOf(m.name);
    ASSERT_NE(killers, nullptr) << m.name << " has no line in suite/mutant_killers.def";
    EXPECT_FALSE(killers->empty()) << m.name;
  }
}

TEST(MutantKillers, EveryLineNamesAKnownMutantOnce) {
  std::set<std::string> seen;
  for (const SceneList& row : mutantKillers()) {
    EXPECT_TRUE(shaders::mutantFromName(row.variant).has_value()) << row.variant;
    EXPECT_NE(row.variant, "none");
    EXPECT_TRUE(seen.insert(row.variant).second) << row.variant << " has two lines";
  }
}

TEST(MutantKillers, EveryKillerIsASuiteScene) {
  const std::set<std::string> cases = suiteCases();
  for (const SceneList& row : mutantKillers())
    for (const std::string& killer : row.scenes) EXPECT_TRUE(cases.count(killer)) << row.variant << ": " << killer;
}

TEST(MutantKillers, ALineOfTheTableReadsAsWritten) {
  // The table's first line, read by hand from suite/mutant_killers.def.
  const std::vector<std::string>* killers = killersOf("distance-clamp-1e-4");
  ASSERT_NE(killers, nullptr);
  EXPECT_EQ(*killers, (std::vector<std::string>{"attenuation.point-5mm-above-floor",
                                                "attenuation.point-3mm-above-floor-close-up"}));
  EXPECT_EQ(killersOf("no-such-mutant"), nullptr);
}

TEST(AdmissibleWitnesses, EveryRealisedVariantHasWitnessesAndNoOtherDoes) {
  for (const shaders::AdmissibleName& a : shaders::admissibleNames()) {
    if (a.name == "none") continue;
    const std::vector<std::string>* witnesses = witnessesOf(a.name);
    if (a.apis == shaders::AdmissibleApis::None) {
      EXPECT_EQ(witnesses, nullptr) << a.name << " is realised by no shader, so it has no witnesses";
      continue;
    }
    ASSERT_NE(witnesses, nullptr) << a.name << " has no line in suite/admissible_witnesses.def";
    EXPECT_FALSE(witnesses->empty()) << a.name;
  }
}

TEST(AdmissibleWitnesses, EveryLineNamesAKnownVariantOnceAndEveryWitnessIsASuiteScene) {
  const std::set<std::string> cases = suiteCases();
  std::set<std::string> seen;
  for (const SceneList& row : admissibleWitnesses()) {
    EXPECT_TRUE(shaders::admissibleFromName(row.variant).has_value()) << row.variant;
    EXPECT_TRUE(seen.insert(row.variant).second) << row.variant << " has two lines";
    for (const std::string& witness : row.scenes) EXPECT_TRUE(cases.count(witness)) << row.variant << ": " << witness;
  }
}

}  // namespace
}  // namespace conformance
