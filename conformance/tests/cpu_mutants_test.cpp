// The CPU mutants (conformance/cpu_mutants.h) change what the backend is
// handed, in the way each is meant to, and nothing else. Expected numbers are
// worked out by hand from SPEC 3.2, 3.6 and 5.3.
#include "conformance/cpu_mutants.h"

#include "baking/bake.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace conformance {
namespace {

lighting::Light mixedPoint(double x, double z, double intensity) {
  lighting::Light l;
  l.type = lighting::LightType::Point;
  l.position = {x, 1, z};
  l.range = 2;
  l.intensity = intensity;
  l.mode = lighting::LightMode::Mixed;
  l.shadows = true;
  return l;
}

// A 2 x 2 static plane with a 1 x 1 lightmap (its one texel centre is the
// origin) under five mixed point lights with shadows, all within 0.6 of each
// other (range 2: all overlap). By luminance * range^2 the four brightest
// take channels 0-3 and the dimmest, light 4 at (0, 1, 0), is demoted.
lighting::Scene demotedScene() {
  lighting::Scene scene;
  scene.name = "cpu-mutants-test";
  scene.image = {8, 8};
  lighting::Object floor;
  floor.mesh.planeSizeX = floor.mesh.planeSizeZ = 2;
  floor.isStatic = true;
  floor.lightmapResolution = 1;
  scene.objects.push_back(floor);
  scene.lights = {mixedPoint(0.3, 0.3, 5), mixedPoint(-0.3, 0.3, 4), mixedPoint(0.3, -0.3, 3),
                  mixedPoint(-0.3, -0.3, 2), mixedPoint(0, 0, 1)};
  return scene;
}

baking::BakeOptions uncached() {
  baking::BakeOptions options;
  options.useCache = false;
  return options;
}

bool isVisible(const lighting::Frame& frame, int light) {
  return std::any_of(frame.selection.visible.begin(), frame.selection.visible.end(),
                     [&](const lighting::VisibleLight& v) { return v.light == light && v.packed >= 0; });
}

TEST(CpuMutants, ShaderMutantsAndTheModelGetTheFrameUnchanged) {
  const auto prepared = baking::prepareBakedScene(demotedScene(), uncached());
  const lighting::Frame frame = lighting::prepareFrame(prepared, 0);
  for (shaders::Mutant m : {shaders::Mutant::None, shaders::Mutant::ShadowStrengthIgnored}) {
    EXPECT_FALSE(isCpuMutant(m));
    EXPECT_EQ(cpuMutantFrame(frame, m).prepared, prepared);
  }
}

TEST(CpuMutants, DemotedLightStillLitPacksTheDemotedLightAndKeepsTheBake) {
  const auto prepared = baking::prepareBakedScene(demotedScene(), uncached());
  ASSERT_TRUE(prepared->shadowMask.demotedLight[4]);  // the premise of the scene
  const lighting::Frame frame = lighting::prepareFrame(prepared, 0);
  EXPECT_FALSE(isVisible(frame, 4));

  const lighting::Frame mutant = cpuMutantFrame(frame, shaders::Mutant::DemotedLightStillLit);
  EXPECT_TRUE(isVisible(mutant, 4));
  EXPECT_EQ(mutant.prepared->shadowMask.channelOfLight[4], -1);  // lit without a mask
  EXPECT_EQ(mutant.prepared->baked, prepared->baked);           // the bake still holds it
  for (int l = 0; l < 4; ++l) EXPECT_EQ(mutant.prepared->shadowMask.channelOfLight[l], l);
  // Built once per scene: a second frame reuses the altered scene.
  EXPECT_EQ(cpuMutantFrame(frame, shaders::Mutant::DemotedLightStillLit).prepared, mutant.prepared);
}

TEST(CpuMutants, LegacyFalloffBakedRebakesWithTheLegacyFalloff) {
  // One baked point light 1 above the texel centre, range 2, intensity 1.
  lighting::Scene scene = demotedScene();
  lighting::Light baked = mixedPoint(0, 0, 1);
  baked.mode = lighting::LightMode::Baked;
  baked.shadows = false;
  scene.lights = {baked};
  const auto prepared = baking::prepareBakedScene(scene, uncached());
  const lighting::Frame frame = lighting::prepareFrame(prepared, 0);
  // Model: rangeAtt / d^2 = (1 - (1/4)^2)^2 / 1 = 225/256.
  EXPECT_NEAR(prepared->baked->objects[0].lightmap.texels[0], 225.0 / 256.0, 1e-6);

  const lighting::Frame mutant = cpuMutantFrame(frame, shaders::Mutant::LegacyFalloffBaked);
  // Legacy: 1 / (1 + 25 d^2 / r^2) = 1 / (1 + 25/4) = 4/29.
  EXPECT_NEAR(mutant.prepared->baked->objects[0].lightmap.texels[0], 4.0 / 29.0, 1e-6);
  EXPECT_NEAR(prepared->baked->objects[0].lightmap.texels[0], 225.0 / 256.0, 1e-6);  // the model's untouched
}

TEST(CpuMutants, ScenesTheMutantCannotChangeKeepTheirFrame) {
  lighting::Scene scene = demotedScene();
  scene.lights.pop_back();       // nobody demoted
  scene.objects[0].isStatic = false;  // no maps
  const auto prepared = baking::prepareBakedScene(scene, uncached());
  const lighting::Frame frame = lighting::prepareFrame(prepared, 0);
  EXPECT_EQ(cpuMutantFrame(frame, shaders::Mutant::DemotedLightStillLit).prepared, prepared);
  EXPECT_EQ(cpuMutantFrame(frame, shaders::Mutant::LegacyFalloffBaked).prepared, prepared);
}

// shaders/shader_interface.def's kinds: the CPU mutants are those this file
// implements.
TEST(CpuMutants, TheTablesCpuMutantsAreTheImplementedOnes) {
  for (const shaders::MutantName& m : shaders::mutantNames())
    EXPECT_EQ(isCpuMutant(m.mutant), m.kind == shaders::MutantKind::Cpu) << m.name;
}

}  // namespace
}  // namespace conformance
