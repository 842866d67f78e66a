// SPEC 3.9's reference shadow maps against values derived by hand: stored
// depths over a plane and a box top, lit and shadowed lookups, the receiver
// offset, the outside rules, the fade, and the intervals of the ambiguous
// cases (a receiver compared against its own depth, a texel at a box's
// silhouette, a lookup on a texel boundary).
#include "lighting/frame.h"
#include "reference/bvh.h"
#include "reference/reference_renderer.h"
#include "reference/shadow_maps.h"
#include "reference/world_triangles.h"
#include "scene_input/scene_loader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

namespace reference {
namespace {

using lighting::Vec3;

// A 10 x 10 plane at y = 0 and a 1 x 1 x 1 box centred at (0, 1.5, 0) (its
// top at y = 2, its bottom at y = 1), lit by `light`, seen from above.
std::shared_ptr<const lighting::PreparedScene> planeAndBox(const std::string& light, const std::string& pipeline = "{}") {
  const std::string text = R"({"lightcts": 1, "image": {"width": 32, "height": 32},
    "camera": {"position": [0, 10, 0], "target": [0, 0, 0], "up": [0, 0, -1], "height": 10},
    "pipeline": )" + pipeline + R"(,
    "objects": [
      {"name": "floor", "mesh": {"type": "plane", "size": [10, 10]}},
      {"name": "box", "mesh": {"type": "box", "size": [1, 1, 1]}, "transform": {"translate": [0, 1.5, 0]}}],
    "lights": [)" + light + "]}";
  return lighting::prepareScene(scene_input::loadSceneText(text, "planeAndBox.json"));
}

struct Built {
  std::shared_ptr<const lighting::PreparedScene> prepared;
  WorldTriangles world;
  std::unique_ptr<Bvh> bvh;
  std::unique_ptr<ReferenceShadowMap> map;
};
Built build(const std::string& light) {
  Built b;
  b.prepared = planeAndBox(light);
  b.world = buildWorldTriangles(*b.prepared);
  b.bvh = std::make_unique<Bvh>(b.world);
  b.map = std::make_unique<ReferenceShadowMap>(lighting::shadowProjection(b.prepared->scene, 0), *b.bvh,
                                               Vec3(0, 10, 0));
  return b;
}

const Vec3 kUp{0, 1, 0};

// Straight down: f = (0, -1, 0), so up = +Z (|f.y| > 0.99), r = cross(f, +Z)
// = (-1, 0, 0), u = cross(r, f) = (0, 0, 1). Extent 4 around the origin:
// depth(q) = (dot(q, f)/4 + 1)/2 = (1 - y/4)/2; mu = (-x/4 + 1)/2, mv = (z/4 + 1)/2.
const std::string kDown = R"({"type": "directional", "direction": [0, -1, 0], "shadows": true,
  "shadow_map": {"resolution": 64, "filter": "hard", "depth_bias": 0.05, "extent": 4}})";

TEST(ShadowMaps, DirectionalMapStoresThePlaneAndTheBoxTop) {
  const Built b = build(kDown);
  ASSERT_EQ(b.map->resolution(), 64);
  // Texel (10, 10): centre mu = mv = 10.5/64, x = -4 (2 mu - 1) = 2.6875: the floor, depth (1 - 0)/2.
  EXPECT_DOUBLE_EQ(b.map->texel(0, 10, 10).depth, 0.5);
  // Texel (32, 32): centre mu = mv = 32.5/64, x = -0.0625, z = 0.0625: the box top y = 2, depth (1 - 0.5)/2.
  EXPECT_DOUBLE_EQ(b.map->texel(0, 32, 32).depth, 0.25);
  // Both far from any edge: a correct pass stores them to within the depth's
  // error only: 8 ULPs of the depth (about 1e-6) and the vertices' position
  // error over the box's depth range each way, under 2e-5 in all.
  EXPECT_LT(b.map->texel(0, 10, 10).hi - b.map->texel(0, 10, 10).lo, 2e-5);
  EXPECT_LT(b.map->texel(0, 32, 32).hi - b.map->texel(0, 32, 32).lo, 2e-5);
}

TEST(ShadowMaps, DirectionalLookupIsShadowedUnderTheBoxAndLitBesideIt) {
  const Built b = build(kDown);
  // Under the box: p' = p + 0.05 L = (0.1, 0.05, 0.1), depth (1 - 0.0125)/2 = 0.49375 > 0.25: shadowed.
  const ShadowLookup under = b.map->lookup({0.1, 0, 0.1}, kUp, {1e-6}, 0x1p-4);
  EXPECT_EQ(under.s, 0.0);
  EXPECT_EQ(under.span(), 0.0);
  // Beside it: 0.49375 <= 0.5: lit.
  const ShadowLookup beside = b.map->lookup({2.7, 0, 2.7}, kUp, {1e-6}, 0x1p-4);
  EXPECT_EQ(beside.s, 1.0);
  EXPECT_EQ(beside.span(), 0.0);
  // Outside the box of half-size 4: s = 1 (SPEC 3.9).
  EXPECT_EQ(b.map->value({4.5, 0, 0}, kUp), 1.0);
}

TEST(ShadowMaps, AReceiverComparedWithItsOwnDepthIsAmbiguous) {
  // No bias: depth(p) equals the texel's own depth, and within the depth
  // error either compare result is correct (acne is admissible).
  const Built b = build(R"({"type": "directional", "direction": [0, -1, 0], "shadows": true,
    "shadow_map": {"resolution": 64, "filter": "hard", "depth_bias": 0, "extent": 4}})");
  const ShadowLookup self = b.map->lookup({2.7, 0, 2.7}, kUp, {1e-6}, 0x1p-4);
  EXPECT_EQ(self.s, 1.0);  // LESS_OR_EQUAL: equal depths are lit
  EXPECT_EQ(self.lo, 0.0);
  EXPECT_EQ(self.hi, 1.0);
}

TEST(ShadowMaps, TexelsAtTheBoxSilhouetteAdmitBothDepths) {
  const Built b = build(kDown);
  // The box's side x = -0.5 sits at mu = (0.5/4 + 1)/2 = 0.5625 = 36/64: a
  // texel edge, not a centre. Texel 35 (centre mu 35.5/64, x = -0.4375)
  // sees the top, texel 36 (x = -0.5625) the floor, each half a texel
  // (0.0625 world units) from the side, far beyond the snapping.
  EXPECT_DOUBLE_EQ(b.map->texel(0, 35, 32).depth, 0.25);
  EXPECT_DOUBLE_EQ(b.map->texel(0, 36, 32).depth, 0.5);
  EXPECT_LT(b.map->texel(0, 35, 32).hi - b.map->texel(0, 35, 32).lo, 2e-5);
  // A map whose texel centre lies on the side: extent 8 and resolution 16
  // put centre 8.5/16 at x = -8 (2 8.5/16 - 1) = -0.5 exactly, where the
  // box top (depth (1 - 2/8)/2 = 0.375) and the floor (0.5) meet.
  const Built coarse = build(R"({"type": "directional", "direction": [0, -1, 0], "shadows": true,
    "shadow_map": {"resolution": 16, "filter": "hard", "extent": 8}})");
  const ShadowTexel& edge = coarse.map->texel(0, 8, 8);
  EXPECT_LE(edge.lo, 0.375);
  EXPECT_GE(edge.hi, 0.5);
}

TEST(ShadowMaps, BilinearWeighsTheFourComparesAndALookupOnTheSilhouetteSpansThem) {
  const Built b = build(R"({"type": "directional", "direction": [0, -1, 0], "shadows": true,
    "shadow_map": {"resolution": 64, "filter": "bilinear", "depth_bias": 0.05, "extent": 4}})");
  // mu = 0.5625 (x = -0.5) is the edge between texels 35 (shadowing, top)
  // and 36 (floor): x = mu N - 0.5 = 35.5, a = 0.5, so s = 0.5 from the
  // floor's side at mv well inside the box (z = 0.1): p = (-0.5, 0, 0.1).
  const ShadowLookup edge = b.map->lookup({-0.5, 0, 0.1}, kUp, {1e-6}, 0x1p-4);
  EXPECT_NEAR(edge.s, 0.5, 1e-12);
  // The weight may be off by 2^-4: [0.4375, 0.5625] at least.
  EXPECT_LE(edge.lo, 0.4375 + 1e-12);
  EXPECT_GE(edge.hi, 0.5625 - 1e-12);
  EXPECT_LT(edge.span(), 0.2);
}

TEST(ShadowMaps, AMoveOnlyTheComparesSeeWidensTheirDepthNotTheWeights) {
  const Built b = build(R"({"type": "directional", "direction": [0, -1, 0], "shadows": true,
    "shadow_map": {"resolution": 64, "filter": "bilinear", "depth_bias": 0.05, "extent": 4}})");
  // On the floor, away from the box: p' = p + 0.05 L, depth 0.49375 against
  // the floor's 0.5, a margin of 0.05 world units in y. A receiver that may
  // move 0.01 further keeps every compare; one that may move 0.1 reaches
  // the texels' depth, and each compare may go either way.
  EXPECT_EQ(b.map->lookup({2.7, 0, 2.7}, kUp, {1e-6, 0.01}, 0x1p-4).span(), 0.0);
  const ShadowLookup flips = b.map->lookup({2.7, 0, 2.7}, kUp, {1e-6, 0.1}, 0x1p-4);
  EXPECT_EQ(flips.lo, 0.0);
  EXPECT_EQ(flips.hi, 1.0);
  // On the silhouette's texel edge the weights follow the position alone: a
  // move of 0.01 the compares alone see (0.0025 in depth, far inside the
  // margin) leaves the interval as it was, the same move of the position
  // shifts the taps by 0.08 texel and widens it by that much each way.
  const ShadowLookup still = b.map->lookup({-0.5, 0, 0.1}, kUp, {1e-6}, 0x1p-4);
  const ShadowLookup depthOnly = b.map->lookup({-0.5, 0, 0.1}, kUp, {1e-6, 0.01}, 0x1p-4);
  const ShadowLookup moved = b.map->lookup({-0.5, 0, 0.1}, kUp, {1e-6 + 0.01}, 0x1p-4);
  EXPECT_DOUBLE_EQ(depthOnly.lo, still.lo);
  EXPECT_DOUBLE_EQ(depthOnly.hi, still.hi);
  EXPECT_GT(moved.span(), still.span() + 0.15);
}

TEST(ShadowMaps, TentOfAUniformRegionIsOneAndItsWeightsSumToOne) {
  const Built b = build(R"({"type": "directional", "direction": [0, -1, 0], "shadows": true,
    "shadow_map": {"resolution": 64, "filter": "tent3x3", "depth_bias": 0.05, "extent": 4}})");
  EXPECT_NEAR(b.map->value({2.7, 0, 2.7}, kUp), 1.0, 1e-12);
  EXPECT_NEAR(b.map->value({0.1, 0, 0.1}, kUp), 0.0, 1e-12);
}

// A spot at (0, 4, 0) pointing down, 90 degrees, near 0.5, range 10: the
// map's depth of a point at distance z below the light is
// far (z - near) / ((far - near) z) = 10 (z - 0.5) / (9.5 z).
TEST(ShadowMaps, SpotMapUsesVulkanDepthAndIsOutsideBehindItsApex) {
  const Built b = build(R"({"type": "spot", "position": [0, 4, 0], "direction": [0, -1, 0], "range": 10,
    "spot_angle_deg": 90, "shadows": true,
    "shadow_map": {"resolution": 64, "filter": "hard", "depth_bias": 0.05, "near": 0.5}})");
  // Texel (10, 10): its ray hits the floor, z = 4 along f.
  EXPECT_NEAR(b.map->texel(0, 10, 10).depth, 10 * 3.5 / (9.5 * 4), 1e-12);
  // Texel (32, 32): the box top, z = 2.
  EXPECT_NEAR(b.map->texel(0, 32, 32).depth, 10 * 1.5 / (9.5 * 2), 1e-12);
  EXPECT_EQ(b.map->value({0.1, 0, 0.1}, kUp), 0.0);
  EXPECT_EQ(b.map->value({3, 0, 1}, kUp), 1.0);
  EXPECT_EQ(b.map->value({0, 5, 0}, kUp), 1.0);   // behind the apex
  EXPECT_EQ(b.map->value({4.5, 0, 0}, kUp), 1.0);  // outside the 90-degree cone (|x| > z)
}

// A point light at (0, 4, 0): the floor under the box is on the -Y face,
// whose depth for a point 4 below is 10 (4 - 0.5) / (9.5 4) as for the spot.
TEST(ShadowMaps, PointCubeStoresEachFaceAndTheFloorIsShadowedUnderTheBox) {
  const Built b = build(R"({"type": "point", "position": [0, 4, 0], "range": 10, "shadows": true,
    "shadow_map": {"resolution": 32, "filter": "hard", "depth_bias": 0.05, "near": 0.5}})");
  ASSERT_EQ(b.map->viewCount(), 6);
  // -Y face (3): sc = +x, tc = -z. Texel (2, 2): direction (x, -1, -z) with
  // x = 2 (2.5/32) - 1 < -0.8, so it sees the floor at y = 0, z_view = 4.
  EXPECT_NEAR(b.map->texel(3, 2, 2).depth, 10 * 3.5 / (9.5 * 4), 1e-12);
  // +Y face (2): nothing above the light.
  EXPECT_EQ(b.map->texel(2, 16, 16).depth, 1.0);
  EXPECT_EQ(b.map->value({0.1, 0, 0.1}, kUp), 0.0);
  EXPECT_EQ(b.map->value({3, 0, 3}, kUp), 1.0);
}

TEST(ShadowMaps, FadeAndStrengthFollowSpec39) {
  EXPECT_EQ(lighting::shadowFade(0, 100), 0.0);
  EXPECT_EQ(lighting::shadowFade(10, 8), 0.0);
  EXPECT_NEAR(lighting::shadowFade(10, 9), 0.5, 1e-15);
  EXPECT_EQ(lighting::shadowFade(10, 11), 1.0);
  EXPECT_EQ(lighting::shadowAttenuation(0, 0.5, 0), 0.5);
  EXPECT_EQ(lighting::shadowAttenuation(0, 1, 0.25), 0.25);
  EXPECT_EQ(lighting::shadowAttenuation(0, 1, 1), 1.0);
  EXPECT_EQ(lighting::shadowAttenuation(1, 1, 0.5), 1.0);  // saturated
}

// The whole reference: a directional light through the box onto the floor,
// the shadowed pixels counted and few of them ambiguous.
TEST(ShadowMaps, ReferenceShadesTheShadowAndCountsItsAmbiguity) {
  auto prepared = planeAndBox(R"({"type": "directional", "direction": [0, -1, 0], "color": [1, 1, 1],
    "intensity": 1, "shadows": true,
    "shadow_map": {"resolution": 128, "filter": "bilinear", "depth_bias": 0.05, "extent": 6}})");
  ReferenceRenderer renderer(prepared);
  const lighting::Frame frame = lighting::prepareFrame(prepared, 0);
  const ReferenceImages images = renderer.render(frame);
  // Pixel (20, 20) of 32 sees the floor at x = -5 + 10 (20.5/32) = 1.40625: lit, N.L = 1.
  EXPECT_NEAR(images.value.at(20, 20, 0), 1.0, 1e-6);
  // The box top is lit; the floor under it is hidden from the camera by the
  // box itself, so the orthographic view from above sees no shadow at all:
  // every floor pixel it sees is lit.
  EXPECT_GT(images.shadowedPixels, 900);
  EXPECT_FALSE(images.shadowAmbiguityExceedsCap());
  // --ideal traces visibility instead and agrees on this scene.
  ReferenceOptions ideal;
  ideal.ideal = true;
  const ReferenceImages exact = renderer.render(frame, ideal);
  EXPECT_NEAR(exact.value.at(20, 20, 0), 1.0, 1e-6);
}

TEST(ShadowMaps, ADiagonalLightCastsTheBoxsShadowWhereTheIdealDoes) {
  // direction (1, -1, 0)/sqrt(2): the box (x in [-0.5, 0.5], y in [1, 2])
  // shadows the floor for x in [0.5, 2.5] (a ray from (x, 0, z) toward
  // -direction = (-1, 1, 0)/sqrt(2) meets the box when x - y in [-0.5, 0.5]
  // for some y in [1, 2]).
  auto prepared = planeAndBox(R"({"type": "directional", "direction": [1, -1, 0], "color": [1, 1, 1],
    "intensity": 1, "shadows": true,
    "shadow_map": {"resolution": 256, "filter": "hard", "depth_bias": 0.05, "extent": 6}})");
  ReferenceRenderer renderer(prepared);
  const lighting::Frame frame = lighting::prepareFrame(prepared, 0);
  const ReferenceImages images = renderer.render(frame);
  ReferenceOptions idealOptions;
  idealOptions.ideal = true;
  const ReferenceImages ideal = renderer.render(frame, idealOptions);
  // Pixel column for x = 1.5: i = (1.5 + 5) / 10 32 - 0.5 = 20.3 -> 20
  // (x = 1.40625); row for z = 0: j = 16 (z = +0.15625). Lit value without
  // shadow: N.L = cos 45 degrees.
  const double lit = std::sqrt(0.5);
  EXPECT_NEAR(images.value.at(20, 16, 0), 0.0, 1e-6);
  EXPECT_NEAR(ideal.value.at(20, 16, 0), 0.0, 1e-6);
  // x = 3.28 (i = 26): beyond the shadow.
  EXPECT_NEAR(images.value.at(26, 16, 0), lit, 1e-6);
  EXPECT_NEAR(ideal.value.at(26, 16, 0), lit, 1e-6);
  EXPECT_FALSE(images.shadowAmbiguityExceedsCap());
}

}  // namespace
}  // namespace reference
