// Every term of SPEC 3 (ambient, lightmap, each light type,
// vertex lights), for both BRDFs, has a suite scene in which all its inputs
// are non-trivial (albedo neither 0 nor 1 in any channel and not grey,
// coloured non-zero ambient, coloured light colours, intensities other than
// 1) and in which the term decides the verdict: taking the term out moves the
// reference beyond its own tolerance on a good part of the image. A term
// whose inputs are 0 or 1 everywhere is untested however many scenes use it.
// The table is docs/model.md's "Which scene tests each term".
#include "baking/bake.h"
#include "lighting/frame.h"
#include "reference/reference_renderer.h"
#include "scene_input/scene_loader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <string>

namespace conformance {
namespace {

using namespace lighting;

enum class Term { Ambient, Lightmap, Directional, Point, Spot, VertexLights };

struct Coverage {
  const char* scene;  // under suite/scenes
  Term term;
  Brdf brdf;
};

const Coverage kCoverage[] = {
    {"brdf/terms-lambert.json", Term::Ambient, Brdf::Lambert},
    {"brdf/terms-lambert.json", Term::Lightmap, Brdf::Lambert},
    {"brdf/terms-lambert.json", Term::Directional, Brdf::Lambert},
    {"brdf/terms-lambert.json", Term::Point, Brdf::Lambert},
    {"brdf/terms-lambert.json", Term::Spot, Brdf::Lambert},
    {"legacy/coloured-vertex-lights.json", Term::VertexLights, Brdf::Lambert},
    {"brdf/terms-srp.json", Term::Ambient, Brdf::Srp},
    {"brdf/terms-srp.json", Term::Lightmap, Brdf::Srp},
    {"brdf/terms-srp.json", Term::Directional, Brdf::Srp},
    {"brdf/terms-srp.json", Term::Point, Brdf::Srp},
    {"brdf/terms-srp.json", Term::Spot, Brdf::Srp},
};

// The term must move at least this share of the compared pixels by more than
// the tolerance (a term that decides the verdict of a pixel or two is too
// easily hidden by max_failing_pixels or the mask).
constexpr double kDecidingShare = 0.05;

bool coloured(const Vec3& c) { return c.r != c.g || c.g != c.b; }
bool strictlyBetween0And1(const Vec3& c) {
  return std::min({c.r, c.g, c.b}) > 0 && std::max({c.r, c.g, c.b}) < 1;
}

// Scene lights whose term this is: realtime lights of the type, baked lights for the lightmap.
bool isTermLight(const Light& l, Term term) {
  switch (term) {
    case Term::Lightmap: return l.mode == LightMode::Baked;
    case Term::Directional: return l.mode != LightMode::Baked && l.type == LightType::Directional;
    case Term::Point: return l.mode != LightMode::Baked && l.type == LightType::Point;
    case Term::Spot: return l.mode != LightMode::Baked && l.type == LightType::Spot;
    default: return false;
  }
}

reference::ReferenceImages referenceOf(const Scene& scene) {
  const auto prepared = baking::prepareBakedScene(scene);
  return reference::ReferenceRenderer(prepared).render(prepareFrame(prepared, 0));
}

// The scene without the term.
Scene withoutTerm(const Scene& scene, Term term) {
  Scene out = scene;
  if (term == Term::Ambient) {
    out.ambient = Vec3(0.0);
  } else if (term == Term::VertexLights) {
    // List positions 4-7 are the least important of the eight, so removing
    // those lights leaves positions 0-3 as they were.
    const Frame frame = prepareFrame(baking::prepareBakedScene(scene), 0);
    std::vector<bool> vertexLight(scene.lights.size(), false);
    for (std::size_t o = 0; o < scene.objects.size(); ++o)
      for (int l : frame.lightsForObject(int(o)).perVertex) vertexLight[l] = true;
    out.lights.clear();
    for (std::size_t l = 0; l < scene.lights.size(); ++l)
      if (!vertexLight[l]) out.lights.push_back(scene.lights[l]);
  } else {
    out.lights.clear();
    for (const Light& l : scene.lights)
      if (!isTermLight(l, term)) out.lights.push_back(l);
  }
  return out;
}

TEST(TermCoverage, EveryTermHasAScene) {
  for (Brdf brdf : {Brdf::Lambert, Brdf::Srp})
    for (Term term : {Term::Ambient, Term::Lightmap, Term::Directional, Term::Point, Term::Spot}) {
      const bool listed = std::any_of(std::begin(kCoverage), std::end(kCoverage),
                                      [&](const Coverage& c) { return c.term == term && c.brdf == brdf; });
      EXPECT_TRUE(listed) << "term " << int(term) << " brdf " << int(brdf);
    }
}

class TermCoverageScene : public ::testing::TestWithParam<Coverage> {};

TEST_P(TermCoverageScene, InputsAreNonTrivialAndTheTermDecidesTheVerdict) {
  const Coverage c = GetParam();
  SCOPED_TRACE(std::string(c.scene) + " term " + std::to_string(int(c.term)));
  const Scene scene = scene_input::loadSceneFile(std::string(LIGHTCTS_SCENES_DIR) + "/" + c.scene);
  for (const Object& o : scene.objects) {
    EXPECT_EQ(o.brdf, c.brdf) << o.name;
    EXPECT_TRUE(strictlyBetween0And1(o.albedo) && coloured(o.albedo)) << o.name << ": albedo";
  }
  EXPECT_TRUE(coloured(scene.ambient) && scene.ambient != Vec3(0.0)) << "ambient";
  int termLights = 0;
  for (const Light& l : scene.lights) {
    EXPECT_TRUE(coloured(l.color)) << l.name << ": colour";
    EXPECT_NE(l.intensity, 1.0) << l.name << ": intensity";
    termLights += isTermLight(l, c.term) ? 1 : 0;
  }
  if (c.term != Term::Ambient && c.term != Term::VertexLights) {
    EXPECT_GT(termLights, 0);
  }
  if (c.term == Term::Lightmap) {
    EXPECT_TRUE(std::any_of(scene.objects.begin(), scene.objects.end(), [](const Object& o) { return o.hasLightmap(); }));
  }

  const reference::ReferenceImages full = referenceOf(scene);
  const reference::ReferenceImages without = referenceOf(withoutTerm(scene, c.term));
  long long compared = 0, decided = 0;
  for (int j = 0; j < full.value.height; ++j)
    for (int i = 0; i < full.value.width; ++i) {
      if (full.value.at(i, j, 3) == 0.0f) continue;
      ++compared;
      bool moved = false;
      for (int ch = 0; ch < 3; ++ch)
        moved = moved || std::abs(full.value.at(i, j, ch) - without.value.at(i, j, ch)) > full.tolerance.at(i, j, ch);
      decided += moved ? 1 : 0;
    }
  EXPECT_GT(double(decided), kDecidingShare * double(compared)) << decided << " of " << compared << " pixels";
}

INSTANTIATE_TEST_SUITE_P(Suite, TermCoverageScene, ::testing::ValuesIn(kCoverage));

}  // namespace
}  // namespace conformance
