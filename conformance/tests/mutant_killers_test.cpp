// The killers table (suite/mutant_killers.def) against what it names: every
// mutant the shaders and the CPU model know has a line, every line names a
// known mutant, and every killer is a scene of suite/scenes.
#include "conformance/mutant_killers.h"
#include "conformance/scene_catalogue.h"
#include "shaders/shader_variant.h"

#include <gtest/gtest.h>

#include <set>

namespace conformance {
namespace {

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
  for (const MutantKillers& row : mutantKillers()) {
    EXPECT_TRUE(shaders::mutantFromName(row.mutant).has_value()) << row.mutant;
    EXPECT_NE(row.mutant, "none");
    EXPECT_TRUE(seen.insert(row.mutant).second) << row.mutant << " has two lines";
  }
}

TEST(MutantKillers, EveryKillerIsASuiteScene) {
  std::set<std::string> cases;
  for (const SceneFile& file : findSceneFiles(LIGHTCTS_SCENES_DIR)) cases.insert(file.caseName());
  for (const MutantKillers& row : mutantKillers())
    for (const std::string& killer : row.killers) EXPECT_TRUE(cases.count(killer)) << row.mutant << ": " << killer;
}

TEST(MutantKillers, ALineOfTheTableReadsAsWritten) {
  // The table's first line, read by hand from suite/mutant_killers.def.
  const std::vector<std::string>* killers = killersOf("distance-clamp-1e-4");
  ASSERT_NE(killers, nullptr);
  EXPECT_EQ(*killers, (std::vector<std::string>{"attenuation.point-5mm-above-floor",
                                                "attenuation.point-3mm-above-floor-close-up"}));
  EXPECT_EQ(killersOf("no-such-mutant"), nullptr);
}

}  // namespace
}  // namespace conformance
