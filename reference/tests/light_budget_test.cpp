// SPEC 5.5's budget maps against counts derived by hand: on floors seen
// straight from above, pixel (i, j) sees the floor point at its centre, and a
// point light at height h with range r reaches it exactly when its horizontal
// distance is below sqrt(r^2 - h^2) (the window of SPEC 3.2 is 0 from d = r
// on; N.L > 0 for any light above the floor). Which lights the model keeps
// follows from each scene's description (SPEC 5.1, 5.2, 4), not from the code.
#include "reference/light_budget.h"

#include "lighting/frame.h"
#include "scene_input/scene_loader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <set>

namespace reference {
namespace {

using lighting::Vec3;

const std::filesystem::path kScenes = std::filesystem::path(LIGHTCTS_SOURCE_DIR) / "suite/scenes";

struct Loaded {
  std::shared_ptr<const lighting::PreparedScene> prepared;
  std::unique_ptr<ReferenceRenderer> renderer;
};

Loaded load(const std::string& scene) {
  Loaded l;
  l.prepared = lighting::prepareScene(scene_input::loadSceneFile((kScenes / scene).string()));
  l.renderer = std::make_unique<ReferenceRenderer>(l.prepared);
  return l;
}

// The floor point at pixel (i, j)'s centre for an orthographic camera looking
// straight down with up = -Z (row 0 toward -Z), or nothing off the floor.
std::optional<Vec3> floorPoint(const lighting::Frame& frame, int i, int j, double floorHalfX, double floorHalfZ) {
  const lighting::Camera& c = frame.view.camera;
  const double pixel = c.orthoHeight / frame.view.height;
  const double x = c.position.x - pixel * frame.view.width / 2 + (i + 0.5) * pixel;
  const double z = c.position.z - c.orthoHeight / 2 + (j + 0.5) * pixel;
  if (std::abs(x) > floorHalfX || std::abs(z) > floorHalfZ) return std::nullopt;
  return Vec3(x, 0, z);
}

bool reachesByHand(const lighting::Light& light, const Vec3& p) {
  const double dx = p.x - light.position.x, dz = p.z - light.position.z, h = light.position.y;
  return dx * dx + dz * dz < light.range * light.range - h * h;
}

// Away from the floor's edge and from a reach circle's rim by this much the
// hand count cannot be off by a rounding of the pixel's position.
bool clearOfEdges(const lighting::Scene& scene, const Vec3& p, double halfX, double halfZ) {
  constexpr double kMargin = 1e-6;
  if (halfX - std::abs(p.x) < kMargin || halfZ - std::abs(p.z) < kMargin) return false;
  for (const lighting::Light& l : scene.lights) {
    const double dx = p.x - l.position.x, dz = p.z - l.position.z, h = l.position.y;
    if (std::abs(std::sqrt(dx * dx + dz * dz) - std::sqrt(l.range * l.range - h * h)) < kMargin) return false;
  }
  return true;
}

TEST(LightBudget, ElevenLightsOnOneObjectKeepTheEightBrightest) {
  // per-object/eleven-lights: one 6 x 6 floor, 11 point lights (h 0.5, r 3):
  // the floor's list holds p3..p10 (the brightest); p0, p1, p2 are cut by
  // the object's 8 wherever they reach.
  const Loaded scene = load("per-object/eleven-lights.json");
  const lighting::Frame frame = lighting::prepareFrame(scene.prepared, 0);
  const LightBudget budget = computeLightBudget(*scene.renderer, frame);
  const auto& lights = frame.scene().lights;
  std::vector<std::int64_t> reachOf(lights.size(), 0);
  int checked = 0, reachedByNine = 0;
  for (int j = 0; j < budget.height; ++j)
    for (int i = 0; i < budget.width; ++i) {
      const std::size_t k = std::size_t(j) * budget.width + i;
      const auto p = floorPoint(frame, i, j, 3, 3);
      if (!p) {
        EXPECT_EQ(budget.reach[k], 0);
        continue;
      }
      if (!clearOfEdges(frame.scene(), *p, 3, 3)) continue;
      int reach = 0, kept = 0;
      std::set<int> lost;
      for (std::size_t l = 0; l < lights.size(); ++l) {
        if (!reachesByHand(lights[l], *p)) continue;
        ++reach;
        ++reachOf[l];
        if (l >= 3) ++kept;
        else lost.insert(int(l));
      }
      ASSERT_EQ(budget.reach[k], reach) << i << ", " << j;
      ASSERT_EQ(budget.kept[k], kept) << i << ", " << j;
      ++checked;
      // A pixel reached by exactly 9 lights of which one is p0, p1 or p2:
      // kept 8, and that one is the light lost.
      if (reach == 9 && lost.size() == 1) {
        ++reachedByNine;
        EXPECT_EQ(budget.kept[k], 8);
      }
    }
  EXPECT_GT(checked, 3000);
  EXPECT_GT(reachedByNine, 0);
  for (const LightBudgetOfLight& l : budget.lights) {
    SCOPED_TRACE(lights[std::size_t(l.light)].name);
    EXPECT_EQ(l.frameCutPixels, 0);
    EXPECT_EQ(l.vertexPixels, 0);
    if (l.light < 3) {
      EXPECT_EQ(l.keptPixels, 0);
      EXPECT_EQ(l.objectCutPixels, l.reachPixels);
    } else {
      EXPECT_EQ(l.keptPixels, l.reachPixels);
      EXPECT_EQ(l.objectCutPixels, 0);
    }
    // Within the few edge pixels left out above.
    EXPECT_NEAR(double(l.reachPixels), double(reachOf[std::size_t(l.light)]), 40.0);
  }
}

TEST(LightBudget, TheSixtyFifthLightIsCutByTheFrame) {
  // limits/sixty-five-lights: p0, the farthest of 65, is dropped by SPEC
  // 5.1; every pixel it reaches lacks it, and no other light is cut.
  const Loaded scene = load("limits/sixty-five-lights.json");
  const lighting::Frame frame = lighting::prepareFrame(scene.prepared, 0);
  const LightBudget budget = computeLightBudget(*scene.renderer, frame);
  const auto& lights = frame.scene().lights;
  std::int64_t p0Pixels = 0, cutPixels = 0;
  for (int j = 0; j < budget.height; ++j)
    for (int i = 0; i < budget.width; ++i) {
      const std::size_t k = std::size_t(j) * budget.width + i;
      const auto p = floorPoint(frame, i, j, 5, 5);
      if (!p || !clearOfEdges(frame.scene(), *p, 5, 5)) continue;
      int reach = 0;
      for (const lighting::Light& l : lights) reach += reachesByHand(l, *p);
      const bool p0 = reachesByHand(lights[0], *p);
      ASSERT_EQ(budget.reach[k], reach) << i << ", " << j;
      ASSERT_EQ(budget.kept[k], reach - (p0 ? 1 : 0)) << i << ", " << j;
      p0Pixels += p0;
      cutPixels += budget.kept[k] < budget.reach[k];
    }
  EXPECT_GT(p0Pixels, 20);
  EXPECT_EQ(cutPixels, p0Pixels);
  for (const LightBudgetOfLight& l : budget.lights) {
    EXPECT_EQ(l.objectCutPixels, 0);
    EXPECT_EQ(l.frameCutPixels, l.light == 0 ? l.reachPixels : 0) << lights[std::size_t(l.light)].name;
  }
  // The loss is the reference's ideal minus its model: only where p0 reaches.
  for (std::size_t k = 0; k < budget.loss.size(); ++k) {
    if (budget.kept[k] == budget.reach[k]) {
      EXPECT_EQ(budget.loss[k], 0.0);
    }
  }
  EXPECT_GT(budget.largestLoss, 0);
  // loss.exr is the full reference's ideal image minus its model image.
  ReferenceOptions ideal;
  ideal.ideal = true;
  const ReferenceImages idealImages = scene.renderer->render(frame, ideal);
  const ReferenceImages modelImages = scene.renderer->render(frame);
  for (int j = 0; j < budget.height; ++j)
    for (int i = 0; i < budget.width; ++i)
      for (int c = 0; c < 3; ++c)
        ASSERT_EQ(budget.lossRgb.at(i, j, c),
                  float(double(idealImages.value.at(i, j, c)) - double(modelImages.value.at(i, j, c))));
}

TEST(LightBudget, PoppingWindowSlidesFrameByFrame) {
  // limits/popping-64: 80 lights on a line (h 0.3, r 0.5); frame f keeps
  // k in [a, a + 63], a = 2 + 2f; every other light reaching a pixel is cut
  // by the frame.
  const Loaded scene = load("limits/popping-64.json");
  const auto& lights = scene.prepared->scene.lights;
  for (int f = 0; f < scene.prepared->scene.frames.count; ++f) {
    SCOPED_TRACE("frame " + std::to_string(f));
    const lighting::Frame frame = lighting::prepareFrame(scene.prepared, f);
    const LightBudget budget = computeLightBudget(*scene.renderer, frame);
    const int a = 2 + 2 * f;
    for (int j = 0; j < budget.height; ++j)
      for (int i = 0; i < budget.width; ++i) {
        const std::size_t k = std::size_t(j) * budget.width + i;
        const auto p = floorPoint(frame, i, j, 6, 2.5);
        if (!p || !clearOfEdges(frame.scene(), *p, 6, 2.5)) continue;
        int reach = 0, kept = 0;
        for (int l = 0; l < int(lights.size()); ++l) {
          if (!reachesByHand(lights[std::size_t(l)], *p)) continue;
          ++reach;
          kept += l >= a && l <= a + 63;
        }
        ASSERT_EQ(budget.reach[k], reach) << i << ", " << j;
        ASSERT_EQ(budget.kept[k], kept) << i << ", " << j;
      }
    for (const LightBudgetOfLight& l : budget.lights) {
      const bool inWindow = l.light >= a && l.light <= a + 63;
      EXPECT_EQ(l.frameCutPixels, inWindow ? 0 : l.reachPixels) << l.light;
    }
  }
}

TEST(LightBudget, LegacyVertexLightsCountAsKept) {
  // legacy/four-pixel-four-vertex: the ball's list holds all 8 lights, pB pG
  // pC pH per pixel and pA pE pD pF per vertex (the scene's description):
  // nothing reaching the ball is lost, and the four vertex lights are kept
  // as vertex lights wherever they reach.
  const Loaded scene = load("legacy/four-pixel-four-vertex.json");
  const lighting::Frame frame = lighting::prepareFrame(scene.prepared, 0);
  const LightBudget budget = computeLightBudget(*scene.renderer, frame);
  EXPECT_EQ(budget.pixelsCut, 0);
  std::int64_t reached = 0;
  for (std::size_t k = 0; k < budget.reach.size(); ++k) {
    EXPECT_EQ(budget.kept[k], budget.reach[k]);
    reached += budget.reach[k] > 0;
  }
  EXPECT_GT(reached, 500);
  const std::set<std::string> vertexLights{"pA", "pE", "pD", "pF"};
  ASSERT_EQ(budget.lights.size(), 8u);
  for (const LightBudgetOfLight& l : budget.lights) {
    const std::string& name = frame.scene().lights[std::size_t(l.light)].name;
    EXPECT_EQ(l.keptPixels, l.reachPixels) << name;
    EXPECT_EQ(l.vertexPixels, vertexLights.contains(name) ? l.reachPixels : 0) << name;
  }
}

TEST(LightBudget, ReachFollowsRangeConeAndFacing) {
  lighting::Light spot;
  spot.type = lighting::LightType::Spot;
  spot.position = {0, 2, 0};
  spot.direction = {0, -1, 0};
  spot.range = 3;
  spot.spotAngleDeg = 90;  // the cone's edge at 45 degrees: |x| = 2 on the floor
  spot.innerSpotAngleDeg = 60;
  const Vec3 up(0, 1, 0);
  EXPECT_TRUE(lightReaches(spot, lighting::Profile::Srp, {1.9, 0, 0}, up));
  EXPECT_FALSE(lightReaches(spot, lighting::Profile::Srp, {2.1, 0, 0}, up));      // outside the cone
  EXPECT_FALSE(lightReaches(spot, lighting::Profile::Srp, {0, 0, 0}, -up));       // facing away
  spot.range = 1.9;
  EXPECT_FALSE(lightReaches(spot, lighting::Profile::Srp, {0, 0, 0}, up));        // d = 2 > range
  spot.range = 3;
  spot.intensity = 0;
  EXPECT_FALSE(lightReaches(spot, lighting::Profile::Srp, {0, 0, 0}, up));        // no colour
  lighting::Light sun;
  sun.type = lighting::LightType::Directional;
  sun.direction = {0, -1, 0};
  EXPECT_TRUE(lightReaches(sun, lighting::Profile::Srp, {5, 0, 5}, up));
  EXPECT_FALSE(lightReaches(sun, lighting::Profile::Srp, {5, 0, 5}, -up));
}

}  // namespace
}  // namespace reference
