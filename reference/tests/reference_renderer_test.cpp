// Whole-image behaviour of the reference: orientation (row 0 at the top),
// background, masks at silhouettes and depth ties, tolerances, and --ideal.
#include "reference/reference_renderer.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>

namespace reference {
namespace {

using namespace lighting;

Object plane(double size, Vec3 translate = {0, 0, 0}) {
  Object o;
  o.mesh.planeSizeX = o.mesh.planeSizeZ = size;
  o.transform.translate = translate;
  return o;
}

Light pointLightAt(Vec3 position, double range, double intensity = 1) {
  Light l;
  l.type = LightType::Point;
  l.position = position;
  l.range = range;
  l.intensity = intensity;
  return l;
}

ReferenceImages render(const Scene& s, bool ideal = false) {
  auto prepared = prepareScene(s);
  ReferenceOptions options;
  options.ideal = ideal;
  return ReferenceRenderer(prepared).render(prepareFrame(prepared, 0), options);
}

Scene smallScene() {
  Scene s;
  s.image = {32, 24};
  return s;
}

TEST(ReferenceRenderer, RowZeroIsTheTopOfTheView) {
  // Default camera looks down with up = (0, 0, -1): the top of the image is -Z.
  Scene s = smallScene();
  s.objects.push_back(plane(20));
  s.lights.push_back(pointLightAt({0, 0.5, -3.5}, 2));
  const ReferenceImages img = render(s);
  int brightestRow = -1;
  float brightest = -1;
  for (int j = 0; j < img.value.height; ++j)
    for (int i = 0; i < img.value.width; ++i)
      if (img.value.at(i, j, 0) > brightest) {
        brightest = img.value.at(i, j, 0);
        brightestRow = j;
      }
  // z = -3.5 of a 10-high view maps to row (0.5 - 3.5/10) * 24 = 3.6.
  EXPECT_GT(brightest, 0.0f);
  EXPECT_NEAR(brightestRow, 3, 1);
}

TEST(ReferenceRenderer, BackgroundIsZeroAndCompared) {
  Scene s = smallScene();
  s.objects.push_back(plane(2));
  s.lights.push_back(pointLightAt({0, 1, 0}, 5));
  const ReferenceImages img = render(s);
  EXPECT_EQ(img.value.at(0, 0, 0), 0.0f);
  EXPECT_EQ(img.value.at(0, 0, 3), 1.0f);
  EXPECT_GT(img.value.at(16, 12, 0), 0.0f);  // the plane, in the middle
  EXPECT_EQ(img.value.at(16, 12, 3), 1.0f);
}

TEST(ReferenceRenderer, SilhouettePixelsAreMaskedInteriorOnesAreNot) {
  // 40 px over 10 m: pixel size 0.25 m, column i has its centre at
  // x = -5 + (i + 0.5) 0.25. A 2 m plane moved by 0.125 has its edges at
  // x = -0.875 and 1.125: through the centres of columns 16 and 24 (masked).
  // Columns 15, 17, 23 and 25 are a whole pixel from an edge (compared).
  Scene s = smallScene();
  s.image = {40, 40};
  s.objects.push_back(plane(2, {0.125, 0, 0}));
  s.lights.push_back(pointLightAt({0, 1, 0}, 5));
  const ReferenceImages img = render(s);
  for (int column : {16, 24}) EXPECT_EQ(img.value.at(column, 20, 3), 0.0f) << column;
  for (int column : {2, 15, 17, 20, 23, 25}) EXPECT_EQ(img.value.at(column, 20, 3), 1.0f) << column;
}

TEST(ReferenceRenderer, CoplanarSurfacesAreMasked) {
  Scene s = smallScene();
  s.objects.push_back(plane(4));
  s.objects.push_back(plane(4, {2, 0, 0}));  // overlaps the first for x in [0, 2]
  s.lights.push_back(pointLightAt({0, 1, 0}, 5));
  const ReferenceImages img = render(s);
  // x = 1 is column (1 + 5) / 10 * 32 = 19.2; x = -1.5 is column 11.2.
  EXPECT_EQ(img.value.at(19, 12, 3), 0.0f);
  EXPECT_EQ(img.value.at(11, 12, 3), 1.0f);
}

// The scene's tolerance_scale is applied by the comparison, once; the
// reference's tolerance is the derivation alone (scaling it here as well
// would apply the scale twice).
TEST(ReferenceRenderer, TolerancesArePositiveFiniteAndUnscaled) {
  Scene s = smallScene();
  s.objects.push_back(plane(20));
  s.lights.push_back(pointLightAt({0.3, 0.7, 0.2}, 4, 3));
  const ReferenceImages a = render(s);
  s.expect.toleranceScale = 4;
  const ReferenceImages b = render(s);
  for (int j = 0; j < a.tolerance.height; ++j)
    for (int i = 0; i < a.tolerance.width; ++i)
      for (int c = 0; c < 3; ++c) {
        const float t = a.tolerance.at(i, j, c);
        ASSERT_TRUE(std::isfinite(t) && t > 0);
        EXPECT_EQ(b.tolerance.at(i, j, c), t);
      }
}

TEST(ReferenceRenderer, FlatShadingHasOnlyArithmeticTolerance) {
  // A directional light on a plane shades every pixel the same, so sub-pixel
  // shifts change nothing and the tolerance is the float32 arithmetic bound
  // (reference/light_terms.h): the normal's error per component (the vertex
  // stage's rotation and the fragment's normalize, reference/surface_inputs.h:
  // under 40 u) over L's components (0.6 + 0.8) and a few roundings of the
  // product, under 100 u relative: 6e-6 of the value.
  Scene s = smallScene();
  s.objects.push_back(plane(20));
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = {0, -0.6, -0.8};
  s.lights.push_back(sun);
  const ReferenceImages img = render(s);
  const float value = img.value.at(16, 12, 0);
  EXPECT_NEAR(value, 2 * 0.6, 1e-6);
  EXPECT_LT(img.tolerance.at(16, 12, 0), 100 * 0x1p-24f * value);
  EXPECT_GT(img.tolerance.at(16, 12, 0), 0.0f);
}

// --tolerance-terms: the tolerance's two parts sum to it (within the float
// rounding of each image), and a point light's gradient gives a shift term.
TEST(ReferenceRenderer, ToleranceTermsSumToTheTolerance) {
  Scene s = smallScene();
  s.objects.push_back(plane(20));
  s.lights.push_back(pointLightAt({0.3, 0.7, 0.2}, 4, 3));
  auto prepared = prepareScene(s);
  ReferenceOptions options;
  options.keepToleranceTerms = true;
  const ReferenceImages img = ReferenceRenderer(prepared).render(prepareFrame(prepared, 0), options);
  ASSERT_EQ(img.toleranceArithmetic.width, img.tolerance.width);
  ASSERT_EQ(img.toleranceShift.height, img.tolerance.height);
  int withShift = 0;
  for (int j = 0; j < img.tolerance.height; ++j)
    for (int i = 0; i < img.tolerance.width; ++i)
      for (int c = 0; c < 3; ++c) {
        const double sum = double(img.toleranceArithmetic.at(i, j, c)) + img.toleranceShift.at(i, j, c);
        EXPECT_NEAR(sum, img.tolerance.at(i, j, c), 1e-6 * img.tolerance.at(i, j, c));
        withShift += img.toleranceShift.at(i, j, c) > 0 ? 1 : 0;
      }
  EXPECT_GT(withShift, 0);
  EXPECT_TRUE(render(s).toleranceShift.pixels.empty()) << "only when asked";
}

TEST(ReferenceRenderer, IdealIgnoresTheBudget) {
  // 65 lights: the budgeted image drops the farthest (light 64 at the corner),
  // the ideal one does not.
  Scene s = smallScene();
  s.objects.push_back(plane(20));
  for (int k = 0; k < 64; ++k) s.lights.push_back(pointLightAt({-3 + 0.1 * (k % 8), 2, -3 + 0.1 * (k / 8)}, 0.5));
  s.lights.push_back(pointLightAt({4.5, 0.5, 3.5}, 1, 5));
  const ReferenceImages budget = render(s), ideal = render(s, true);
  // (4.5, 3.5) is column (4.5 + 6.67) / 13.33 * 32 = 26.8, row (3.5 + 5) / 10 * 24 = 20.4.
  EXPECT_EQ(budget.value.at(26, 20, 0), 0.0f);
  EXPECT_GT(ideal.value.at(26, 20, 0), 0.1f);
}

// valueOnly (the benchmarks' baseline, the light budgets' and the sharpness'
// renders): the same value and mask, bit for bit, as a full render, ideal or
// the model's, with silhouettes (masked by the traced shifts), 65 point
// lights, a shadowed spot and a directional light in view, no tolerance, and
// one shading a pixel, its light sums without their bounds.
TEST(ReferenceRenderer, ValueOnlyKeepsValueAndMaskBitForBit) {
  Scene s = smallScene();
  s.image = {40, 40};
  s.objects.push_back(plane(20));
  s.objects.push_back(plane(2, {0.125, 0.3, 0}));  // silhouettes over the floor
  for (int k = 0; k < 65; ++k) s.lights.push_back(pointLightAt({-3 + 0.1 * (k % 8), 1 + 0.05 * (k / 8), -3 + 0.1 * (k / 8)}, 6));
  Light spot;  // the spot and directional terms, and a shadow of the small plane
  spot.position = {0.5, 3, 0.2};
  spot.shadows = true;
  s.lights.push_back(spot);
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = glm::normalize(Vec3(0.3, -1, 0.2));
  sun.intensity = 0.5;
  s.lights.push_back(sun);
  auto prepared = prepareScene(s);
  const ReferenceRenderer renderer(prepared);
  const Frame frame = prepareFrame(prepared, 0);
  for (const bool ideal : {true, false}) {
    SCOPED_TRACE(ideal ? "ideal" : "the model");
    const ReferenceImages full = renderer.render(frame, {.ideal = ideal});
    const ReferenceImages value = renderer.render(frame, {.ideal = ideal, .valueOnly = true});
    ASSERT_EQ(value.value.pixels.size(), full.value.pixels.size());
    int masked = 0;
    for (std::size_t k = 0; k < full.value.pixels.size(); ++k) {
      ASSERT_EQ(std::bit_cast<std::uint32_t>(value.value.pixels[k]),
                std::bit_cast<std::uint32_t>(full.value.pixels[k]))
          << "float " << k;
      masked += k % 4 == 3 && full.value.pixels[k] == 0.0f ? 1 : 0;
    }
    EXPECT_GT(masked, 0) << "the scene has masked pixels";
    EXPECT_EQ(value.maskedPixels, full.maskedPixels);
    for (const float t : value.tolerance.pixels) ASSERT_EQ(t, 0.0f);
    // Up to nine shadings a compared pixel in the full render (the centre and
    // eight shifts on the same surface), one here.
    EXPECT_LT(5 * value.lightEvaluations, full.lightEvaluations + full.lightEvaluations / 10);
    EXPECT_GT(value.lightEvaluations, 0);
  }
}

}  // namespace
}  // namespace reference
