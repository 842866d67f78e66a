// The deferred light buffers in the reference (SPEC 3.7), against values
// worked out by hand in docs/tolerances.md "Deferred buffers": ldr8
// saturates at log2(255), the hdr16 bound of a few lights, the ldr8 decode
// bound at the sums of SPEC 10's deferred cases, and the reconstruction term.
#include "reference/deferred_buffers.h"

#include "reference/reference_renderer.h"
#include "reference/tolerance_model.h"

#include <gtest/gtest.h>

#include <cmath>

namespace reference {
namespace {

using namespace lighting;
namespace tol = tolerance;

const double kLog2Of255 = 7.994353436858858;  // log2(255)

TEST(DeferredBuffers, Ldr8DecodeSaturatesAtLog2Of255) {
  EXPECT_DOUBLE_EQ(decodedLightSum(DeferredBuffer::Ldr8, 20.0), kLog2Of255);
  EXPECT_DOUBLE_EQ(decodedLightSum(DeferredBuffer::Ldr8, 8.5), kLog2Of255);
  EXPECT_NEAR(decodedLightSum(DeferredBuffer::Ldr8, 7.9), 7.9, 1e-12);
  EXPECT_NEAR(decodedLightSum(DeferredBuffer::Ldr8, 1.0), 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(decodedLightSum(DeferredBuffer::Ldr8, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(decodedLightSum(DeferredBuffer::Hdr32, 20.0), 20.0);
  EXPECT_DOUBLE_EQ(decodedLightSum(DeferredBuffer::Hdr16, 20.0), 20.0);
}

TEST(DeferredBuffers, Hdr16BoundOfThreeLights) {
  // (k + 1) 2^-10 S + 2 k 2^-14 with k = 3, S = 1.5: either neighbour of
  // each conversion, 1 ULP of a half:
  // 4 * 1.5 / 1024 + 6 / 16384 = 0.005859375 + 0.0003662109375.
  EXPECT_DOUBLE_EQ(hdr16BlendBound(1.5, 3), 0.0062255859375);
  EXPECT_DOUBLE_EQ(hdr16BlendBound(0.0, 0), 0.0);
}

TEST(DeferredBuffers, Ldr8BoundAtTheSumsOfSpecTen) {
  const double log2Error = tol::kLdr8DecodeAbsError;
  // S = 0 (nothing added): the clear value 1 stays 1, but log2(1) may be
  // off by log2's absolute 2^-21 (inside [0.5, 2]): the decode error alone.
  EXPECT_EQ(ldr8DecodeBound(0.0, 0, 0.0), log2Error);
  // A conversion may return either of the two closest grid values (a whole
  // step). S = 1, one light: x = 0.5 = 127.5 / 255, within one step of
  // 126.5..128.5: 127 or 128 may be stored.
  // -log2(127/255) - 1 = 0.0056693...; 1 + log2(128/255) = 0.0056466...
  EXPECT_NEAR(ldr8DecodeBound(1.0, 1, 0.0), std::log2(255.0 / 127.0) - 1.0 + log2Error, 1e-9);
  // Two lights: three conversions, 3 steps: 124.5..130.5, so 125..130;
  // log2(255/125) - 1 = 0.0285691 beats 1 + log2(130/255) = 0.0280239.
  EXPECT_NEAR(ldr8DecodeBound(1.0, 2, 0.0), std::log2(255.0 / 125.0) - 1.0 + log2Error, 1e-9);
  // S = 7.9: x = 255 * 2^-7.9 = 1.0677 steps, within one step of 0.07..2.07:
  // n = 1 (decodes to log2(255), 0.0944 above 7.9) or n = 2 (log2(127.5),
  // 0.9056 below): the larger.
  EXPECT_NEAR(ldr8DecodeBound(7.9, 1, 0.0), 7.9 - std::log2(127.5) + log2Error, 1e-9);
  // S = 8.5 and S = 20: x < 1/255, saturated, and only n = 0 or 1 (both
  // decoding to log2(255)) can be stored: nothing but the log2 error.
  EXPECT_NEAR(ldr8DecodeBound(8.5, 1, 0.0), log2Error, 1e-12);
  EXPECT_NEAR(ldr8DecodeBound(20.0, 1, 0.0), log2Error, 1e-12);
}

// A pixel where the reference's light terms are exactly 0 but float32 terms
// may not be (near a range or cone edge): a GPU term c <= sumBound = 0.01
// encodes exp2(-c) >= 2^-0.01 = 0.99309 = 253.24 / 255, and one conversion may
// go a whole step further: 252.24 / 255, so n = 253 is possible, decoding to
// log2(255/253) = 0.011360 away from 0.
TEST(DeferredBuffers, Ldr8BoundWhereOnlyFloatErrorCouldAddLight) {
  EXPECT_EQ(ldr8DecodeBound(0.0, 0, 0.0), tol::kLdr8DecodeAbsError);
  EXPECT_NEAR(ldr8DecodeBound(0.0, 0, 0.01), std::log2(255.0 / 253.0) + tol::kLdr8DecodeAbsError, 1e-9);
}

// A large error of the sum is not linearised: S = 2, e = 1 gives encoded
// values in [2^-3, 2^-1] = [31.875, 127.5] / 255, one step wider: 31..128
// (n = 30.875 rounds up to 31); decoded -log2(31/255) = 3.040 and
// -log2(128/255) = 0.994, so the bound is 3.040 - 2 = 1.040 (a linear
// ln2 x e would give about 0.69 x 0.25 = 0.17 of x: far too little).
TEST(DeferredBuffers, Ldr8BoundCoversALargeSumErrorExactly) {
  EXPECT_NEAR(ldr8DecodeBound(2.0, 1, 1.0), std::log2(255.0 / 31.0) - 2.0 + tol::kLdr8DecodeAbsError, 1e-6);
}

Scene ldr8Plane(double albedo, double intensity) {
  Scene s;
  s.image = {16, 16};
  s.pipeline.path = RenderPath::Deferred;
  s.pipeline.deferredBuffer = DeferredBuffer::Ldr8;
  s.ambient = {0.1, 0.1, 0.1};
  Object plane;
  plane.mesh.planeSizeX = plane.mesh.planeSizeZ = 20;  // fills the 10-high view
  plane.albedo = {albedo, albedo, albedo};
  s.objects.push_back(plane);
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = {0, -1, 0};  // straight down onto the plane: N.L = 1
  sun.intensity = intensity;
  s.lights.push_back(sun);
  return s;
}

TEST(DeferredBuffers, ReferenceValueOfLdr8WithSumTwenty) {
  // Albedo 1, intensity 20: light sum 20 saturates; base = 1 * 0.1.
  auto prepared = prepareScene(ldr8Plane(1.0, 20.0));
  const ReferenceImages img = ReferenceRenderer(prepared).render(prepareFrame(prepared, 0));
  EXPECT_NEAR(img.value.at(8, 8, 0), 0.1 + kLog2Of255, 1e-6);
  EXPECT_EQ(img.value.at(8, 8, 3), 1.0f);  // compared
  // Saturated: the tolerance is the log2 error and float roundings, tiny.
  EXPECT_LT(img.tolerance.at(8, 8, 0), 1e-4);
}

TEST(DeferredBuffers, ReferenceValueOfLdr8WithSumOne) {
  // Albedo 0.05, intensity 20: light sum 1, value 0.05 * 0.1 + 1; tolerance
  // at least the tie at 127.5 / 255.
  auto prepared = prepareScene(ldr8Plane(0.05, 20.0));
  const ReferenceImages img = ReferenceRenderer(prepared).render(prepareFrame(prepared, 0));
  EXPECT_NEAR(img.value.at(8, 8, 0), 0.005 + 1.0, 1e-6);
  EXPECT_GE(img.tolerance.at(8, 8, 0), std::log2(255.0 / 127.0) - 1.0);
  EXPECT_LT(img.tolerance.at(8, 8, 0), 0.0058);
}

TEST(DeferredBuffers, ForwardAndHdr32AgreeOnTheValue) {
  Scene s = ldr8Plane(0.5, 3.0);
  s.pipeline.deferredBuffer = DeferredBuffer::Hdr32;
  auto deferred = prepareScene(s);
  s.pipeline.path = RenderPath::Forward;
  auto forward = prepareScene(s);
  const ReferenceImages d = ReferenceRenderer(deferred).render(prepareFrame(deferred, 0));
  const ReferenceImages f = ReferenceRenderer(forward).render(prepareFrame(forward, 0));
  // 0.5 * 0.1 + 0.5 * 3 = 1.55 in both.
  EXPECT_NEAR(d.value.at(8, 8, 0), 1.55, 1e-6);
  EXPECT_EQ(d.value.at(8, 8, 0), f.value.at(8, 8, 0));
  // Deferred adds the reconstruction and per-light product terms.
  EXPECT_GE(d.tolerance.at(8, 8, 0), f.tolerance.at(8, 8, 0));
}

// Default camera: orthographic, 10 high, near 0.1, far 100, at (0, 10, 0)
// looking down; a square 16-pixel image. At p = (0, 0, 0), 10 below the
// camera, the arithmetic of the reconstruction is, in steps u of one GPU
// operation's rounding (2^-23, tolerance_model.h's kStepRoundoff),
//   depth:  12 u (100 - 0.1)               = 1198.8 u
//   ndc:    13 u sqrt(2) * 5 (half height)  = 91.92 u
//   matrix: 16 u * 10                        = 160 u
double reconstructionAtTheOriginOfTheDefaultView(double vertexSnap) {
  Scene s;
  s.image = {16, 16};
  const Frame frame = prepareFrame(prepareScene(s), 0);
  return reconstructionPositionError(frame.view, Vec3(0.0), vertexSnap);
}

const double kDefaultViewArithmetic = (12.0 * 99.9 + 13.0 * std::sqrt(2.0) * 5.0 + 160.0) * tol::kStepRoundoff;

TEST(DeferredBuffers, ReconstructionErrorOfAnOrthographicView) {
  // Without snapping (a device that keeps every bit): the arithmetic alone.
  EXPECT_NEAR(reconstructionAtTheOriginOfTheDefaultView(0.0), kDefaultViewArithmetic, 1e-12);
}

TEST(DeferredBuffers, ReconstructionErrorOfASnappedGBuffer) {
  // Vertices snapped to 1/16 pixel: the depth the G-buffer stored is that of
  // a point up to 1/16 pixel from the centre on each axis, of a 10 / 16 =
  // 0.625 m pixel, and the light pass puts it on the centre's ray:
  // sqrt(2) / 16 * 0.625 m across the view axis, beside the arithmetic.
  EXPECT_NEAR(reconstructionAtTheOriginOfTheDefaultView(1.0 / 16),
              kDefaultViewArithmetic + std::sqrt(2.0) / 16.0 * 0.625, 1e-12);
}

}  // namespace
}  // namespace reference
