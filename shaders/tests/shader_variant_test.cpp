// The mutants (SPEC 7) are test-only: the default variant is the model, every
// --mutant spelling round-trips, and each reaches the MUTANT constant.
#include "shaders/shader_constants.h"
#include "shaders/shader_variant.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace shaders {
namespace {

TEST(ShaderVariant, DefaultIsTheSpecialisedModelWithoutMutant) {
  const ShaderVariant variant;
  EXPECT_TRUE(variant.specialised);
  EXPECT_EQ(variant.mutant, Mutant::None);
  EXPECT_EQ(constantValues(lighting::ShaderFeatures{}, variant)[kMutant], 0);
  EXPECT_EQ(mutantFromName("none"), Mutant::None);
  EXPECT_EQ(mutantName(Mutant::None), "none");
}

// The forward pass looks up every slot in use (-1, shader_interface.def); a light
// pass its light's own slots, -2 for a kind it has none of; the full shader
// keeps every slot in the light pass too.
TEST(ShaderVariant, ALightPassLooksUpItsLightsSlotsAlone) {
  const ShaderVariant specialised;
  const ConstantValues frame = constantValues(lighting::ShaderFeatures{}, specialised);
  EXPECT_EQ(frame[kLightCookieSlot], -1);
  EXPECT_EQ(frame[kLightShadowSlot], -1);
  const ConstantValues light = lightPassConstants(frame, {3, -1}, specialised);
  EXPECT_EQ(light[kLightCookieSlot], 3);
  EXPECT_EQ(light[kLightShadowSlot], -2);
  for (std::uint32_t id = 0; id < kLightCookieSlot; ++id) EXPECT_EQ(light[id], frame[id]) << id;
  ShaderVariant full;
  full.specialised = false;
  const ConstantValues fullFrame = constantValues(lighting::ShaderFeatures{}, full);
  EXPECT_EQ(lightPassConstants(fullFrame, {3, 5}, full), fullFrame);
}

TEST(ShaderVariant, EveryMutantNameRoundTrips) {
  std::set<int> numbers;
  std::set<std::string> names;
  for (const MutantName& m : mutantNames()) {
    SCOPED_TRACE(std::string(m.name));
    EXPECT_NE(m.mutant, Mutant::None);
    EXPECT_FALSE(m.what.empty());
    EXPECT_EQ(mutantFromName(m.name), m.mutant);
    EXPECT_EQ(mutantName(m.mutant), m.name);
    EXPECT_TRUE(numbers.insert(static_cast<int>(m.mutant)).second) << "number used twice";
    EXPECT_TRUE(names.insert(std::string(m.name)).second) << "name used twice";
    ShaderVariant variant;
    variant.mutant = m.mutant;
    EXPECT_EQ(constantValues(lighting::ShaderFeatures{}, variant)[kMutant], static_cast<int>(m.mutant));
  }
  // The numbers are dense from 1, as shaders/shader_interface.def numbers them.
  for (int i = 1; i <= int(numbers.size()); ++i) EXPECT_TRUE(numbers.count(i)) << i;
  EXPECT_GE(mutantNames().size(), 12u);
  EXPECT_EQ(mutantFromName("no-such-mutant"), std::nullopt);
  EXPECT_EQ(mutantFromName(""), std::nullopt);
}

// SPEC 7: each mutant must be caught on every backend, so each needs its
// scenes in the killers' table (suite/mutant_killers.def).
// That every mutant has killers is checked beside the killers' table
// (conformance/tests/mutant_killers_test.cpp).

// SPEC 3.9: lit when depth(p') <= texel. Only shadow-compare-less changes
// the samplers' compare, and only to LESS.
TEST(ShaderVariant, OnlyTheShadowCompareMutantChangesTheShadowLookupCompare) {
  EXPECT_EQ(lighting::kShadowLookupCompare, lighting::DepthCompare::LessOrEqual);
  for (const MutantName& m : mutantNames())
    EXPECT_EQ(shadowLookupCompare(m.mutant),
              m.mutant == Mutant::ShadowCompareLess ? lighting::DepthCompare::Less : lighting::DepthCompare::LessOrEqual)
        << m.name;
  EXPECT_EQ(shadowLookupCompare(Mutant::None), lighting::DepthCompare::LessOrEqual);
}

// shader_interface.def's kinds: a pipeline mutant, and only a pipeline
// mutant, changes the light volumes' rule or the shadow samplers' compare.
TEST(ShaderVariant, ThePipelineMutantsAreThoseThatChangeThePipelineState) {
  for (const MutantName& m : mutantNames()) {
    const bool changesState = volumeRule(m.mutant) != lighting::VolumeRule::Model ||
                              shadowLookupCompare(m.mutant) != lighting::kShadowLookupCompare;
    EXPECT_EQ(changesState, m.kind == MutantKind::Pipeline) << m.name;
  }
}

}  // namespace
}  // namespace shaders
