// Every backend that this build and machine can create against the independent
// double-precision evaluation of SPEC 1 and 3 on plane scenes
// (testing/independent_plane), to 1e-3 relative, with no NaN or infinity in
// any channel of any pixel. The scenes are the six of the reference's
// independent test (reference/tests/independent_plane_test.cpp) that a backend
// draws (not --ideal): orthographic, perspective, perspective far from the
// origin (1e5), a light on the surface, per-object truncation and legacy
// vertex lights. Each is written out as SPEC 2 JSON to a file, loaded with the
// project's loader, prepared (SPEC 5) and rendered as `lightcts render` does
// (the shipped, specialised shader), with validation on so that any layer
// message fails the render.
//
// Per pixel:
//  - all four channels are finite and A == 1 (the backends clear A to 1 and
//    write 1 where they draw), background and edge pixels included;
//  - pixels whose centre lies within kEdgeDistancePx = 1/8 pixel of the
//    plane's edge in the image (independent_plane::nearPlaneEdge: the same
//    distance the reference masks as don't care on a 4-bit device, SPEC 6,
//    because vertex snapping may move the edge by sqrt(2)/16 pixel) are not
//    compared further: either side of the edge is a correct result;
//  - background (the ray misses the plane): RGB exactly 0;
//  - on the plane: |rendered - expected| <= 1e-3 * |expected| + floor +
//    snapping per RGB channel, floor as derived at kAbsoluteFloorUlps below.
//    Snapping: Vulkan keeps subPixelPrecisionBits = b fractional bits of each
//    vertex's x and y (OpenGL: GL_SUBPIXEL_BITS) and gives no rounding
//    direction, so each vertex may move by up to 2^-b pixel on each axis, on
//    its own, and a pixel centre then sees the plane's point of a position
//    up to 2^-b away on each axis. The model's own value at the centre moved
//    by 2^-b along x and along y (both ways) bounds it to first order: the
//    larger change along x plus the larger along y. b is the device's.
#include "backends/backend.h"
#include "backends/tests/backend_combinations.h"
#include "baking/bake.h"
#include "lighting/frame.h"
#include "scene_input/scene_loader.h"
#include "testing/independent_plane/independent_plane_model.h"

#include <glm/common.hpp>
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace independent_plane;

// The acceptance bound: 1e-3 relative per channel.
constexpr double kRelativeTolerance = 1e-3;

// The absolute floor, in float32 unit roundoffs (u = 2^-24) of the pixel's
// largest single light contribution (albedo * one light's term, its largest
// channel). A correct float32 implementation rounds that term, the running sum
// it is added to and the albedo product each to the nearest float, so its
// result may carry a few u of the largest term it summed whatever the exact
// value of the channel; a channel far smaller than that term cannot be held
// to 1e-3 of itself below those roundings. 8 u = 4.8e-7 of the largest
// contribution: a handful of roundings, and within the 1e-6 of it that the
// acceptance rule allows. In these scenes every albedo and light-colour
// channel is at least 1/4 of the largest and the ambient term is positive,
// so 1e-3 of the expected value exceeds this floor on every pixel of the
// plane; the floor only guards a channel whose exact value is (nearly) 0
// from a 0/0 test.
constexpr double kAbsoluteFloorUlps = 8;
constexpr double kUnitRoundoff = 0x1p-24;

constexpr int kReportedFailures = 5;

struct Worst {
  double relative = 0;
  int i = -1, j = -1, channel = -1;
  double rendered = 0, expected = 0;
};

struct BackendResult {
  Worst worst;
  int comparedOnPlane = 0;
  int background = 0;
  int nearEdge = 0;
};

std::string describe(const std::string& backend, const SceneSpec& s, int i, int j) {
  std::ostringstream out;
  out << "[" << backend << "] " << s.name << " pixel (" << i << ", " << j << ")";
  return out.str();
}

// Per pixel and channel, how far the device's vertex snapping (2^-b pixel
// each way on each axis) may move the model's value: the larger change of
// the two moves along x plus the larger of the two along y. A moved centre
// that leaves the plane falls within kEdgeDistancePx, where nothing is compared.
std::vector<Vec> snappingAllowance(const SceneSpec& s, const AppliedLights& applied,
                                   const std::vector<ExpectedPixel>& centre, int subPixelBits) {
  const double snap = std::ldexp(1.0, -std::max(subPixelBits, 4));
  std::vector<Vec> axis[2] = {std::vector<Vec>(centre.size(), Vec(0.0)), std::vector<Vec>(centre.size(), Vec(0.0))};
  const double moves[4][2] = {{snap, 0}, {-snap, 0}, {0, snap}, {0, -snap}};
  for (int m = 0; m < 4; ++m) {
    const std::vector<ExpectedPixel> moved = expectedPixels(s, applied, moves[m][0], moves[m][1]);
    for (std::size_t k = 0; k < centre.size(); ++k)
      axis[m / 2][k] = glm::max(axis[m / 2][k], glm::abs(moved[k].value - centre[k].value));
  }
  std::vector<Vec> allowance(centre.size());
  for (std::size_t k = 0; k < centre.size(); ++k) allowance[k] = axis[0][k] + axis[1][k];
  return allowance;
}

// Compares one backend's image with the model; reports through gtest.
BackendResult compareImage(const std::string& backend, const SceneSpec& s, const imaging::Image& image,
                           const std::vector<ExpectedPixel>& expected, const std::vector<Vec>& snapping) {
  BackendResult result;
  EXPECT_EQ(image.width, s.width) << "[" << backend << "] " << s.name;
  EXPECT_EQ(image.height, s.height) << "[" << backend << "] " << s.name;
  EXPECT_EQ(image.channels, 4) << "[" << backend << "] " << s.name;
  if (image.width != s.width || image.height != s.height || image.channels != 4) return result;

  int nonFinite = 0, badAlpha = 0, badBackground = 0, failures = 0;
  for (int j = 0; j < s.height; ++j)
    for (int i = 0; i < s.width; ++i) {
      for (int c = 0; c < 4; ++c) {
        const float v = image.at(i, j, c);
        if (!std::isfinite(v) && ++nonFinite <= kReportedFailures)
          ADD_FAILURE() << describe(backend, s, i, j) << " channel " << c << ": " << v << " is not finite";
      }
      const float alpha = image.at(i, j, 3);
      if (alpha != 1.0f && ++badAlpha <= kReportedFailures)
        ADD_FAILURE() << describe(backend, s, i, j) << ": A = " << alpha << ", expected 1";

      const ExpectedPixel& e = expected[std::size_t(j) * s.width + i];
      if (e.nearEdge) {
        ++result.nearEdge;
        continue;
      }
      if (!e.onPlane) {
        ++result.background;
        for (int c = 0; c < 3; ++c) {
          const float v = image.at(i, j, c);
          if (v != 0.0f && ++badBackground <= kReportedFailures)
            ADD_FAILURE() << std::setprecision(9) << describe(backend, s, i, j) << " channel " << c
                          << ": background is " << v << ", expected exactly 0";
        }
        continue;
      }
      ++result.comparedOnPlane;
      const double floor = kAbsoluteFloorUlps * kUnitRoundoff * e.largestLightContribution;
      for (int c = 0; c < 3; ++c) {
        const double rendered = image.at(i, j, c);
        const double want = e.value[c];
        const double diff = std::abs(rendered - want);
        const double allowed =
            kRelativeTolerance * std::abs(want) + floor + snapping[std::size_t(j) * s.width + i][c];
        const double relative = want != 0.0 ? diff / std::abs(want)
                                            : (diff == 0.0 ? 0.0 : std::numeric_limits<double>::infinity());
        // A NaN counts as the worst (it also failed the finiteness check).
        if (!(relative <= result.worst.relative))
          result.worst = {std::isnan(relative) ? std::numeric_limits<double>::infinity() : relative, i, j, c,
                          rendered, want};
        if (!(diff <= allowed) && ++failures <= kReportedFailures)
          ADD_FAILURE() << std::setprecision(9) << describe(backend, s, i, j) << " channel " << c << ": rendered "
                        << rendered << ", expected " << want << ", difference " << diff << " (allowed " << allowed
                        << " = 1e-3 * |expected| + floor " << floor << " + snapping "
                        << snapping[std::size_t(j) * s.width + i][c] << "; relative " << relative << ")";
      }
    }
  EXPECT_EQ(nonFinite, 0) << "[" << backend << "] " << s.name << ": channels that are NaN or infinite";
  EXPECT_EQ(badAlpha, 0) << "[" << backend << "] " << s.name << ": pixels with A != 1";
  EXPECT_EQ(badBackground, 0) << "[" << backend << "] " << s.name << ": background channels that are not 0";
  EXPECT_EQ(failures, 0) << "[" << backend << "] " << s.name << ": channels outside 1e-3 relative (first "
                         << kReportedFailures << " shown)";
  // Not a vacuous pass: most of each scene is the plane, and the edge is thin.
  EXPECT_GT(result.comparedOnPlane, s.width * s.height / 3) << "[" << backend << "] " << s.name;
  EXPECT_LT(result.nearEdge, s.width * s.height / 20) << "[" << backend << "] " << s.name;
  return result;
}

// Writes the scene's JSON to a temporary file and loads it as the CLI would.
std::shared_ptr<const lighting::PreparedScene> loadThroughFile(const SceneSpec& s) {
  const std::filesystem::path path = std::filesystem::path(::testing::TempDir()) /
                                     ("lightcts-" + s.name + "-" + std::to_string(::getpid()) + ".json");
  {
    std::ofstream out(path);
    out << sceneJson(s);
    if (!out) throw std::runtime_error("cannot write " + path.string());
  }
  lighting::Scene scene;
  try {
    scene = scene_input::loadSceneFile(path.string());
  } catch (...) {
    std::filesystem::remove(path);
    throw;
  }
  std::filesystem::remove(path);
  return baking::prepareBakedScene(std::move(scene));
}

// Renders the case on one backend and driver and compares; a skip when that
// combination is not supported here.
void checkOnBackend(const PlaneCase& planeCase, const backends::testing::Combination& combination) {
  const SceneSpec& s = planeCase.scene;
  SCOPED_TRACE("scene " + s.name);
  const auto prepared = loadThroughFile(s);
  const lighting::Frame frame = lighting::prepareFrame(prepared, 0);
  const std::vector<ExpectedPixel> expected = expectedPixels(s, planeCase.applied);

  std::string whyNot;
  const std::unique_ptr<backends::Backend> backend = backends::testing::createOrNull(combination, whyNot);
  if (!backend) GTEST_SKIP() << whyNot;
  const std::string& name = combination.suffix;
  imaging::Image image;
  try {
    image = backend->render(frame);
  } catch (const std::exception& e) {
    FAIL() << "[" << name << "] " << s.name << ": rendering failed: " << e.what();
  }
  const BackendResult r = compareImage(
      name, s, image, expected,
      snappingAllowance(s, planeCase.applied, expected, backend->device().subPixelPrecisionBits));
  std::ostringstream worst;
  worst << std::setprecision(3) << r.worst.relative;
  ::testing::Test::RecordProperty("worst_relative_error_" + name, worst.str());
  std::printf(
      "[ %s on %s (%s) ] worst relative error %.3g at pixel (%d, %d) channel %d: rendered %.9g, expected %.9g; "
      "%d pixels compared on the plane, %d background, %d within 1/8 pixel of the edge\n",
      s.name.c_str(), name.c_str(), backend->device().name.c_str(), r.worst.relative, r.worst.i, r.worst.j,
      r.worst.channel, r.worst.rendered, r.worst.expected, r.comparedOnPlane, r.background, r.nearEdge);
}

class IndependentPlaneBackend : public ::testing::TestWithParam<backends::testing::Combination> {};

TEST_P(IndependentPlaneBackend, Orthographic) { checkOnBackend(orthographicCase(), GetParam()); }

TEST_P(IndependentPlaneBackend, Perspective) { checkOnBackend(perspectiveCase(), GetParam()); }

TEST_P(IndependentPlaneBackend, PerspectiveFarFromOrigin) { checkOnBackend(perspectiveFarCase(), GetParam()); }

TEST_P(IndependentPlaneBackend, LightOnTheSurface) {
  const PlaneCase c = lightOnSurfaceCase();
  // The pixels under "p_on" (16, 16) and "p_low" (8, 20) must be compared.
  const std::vector<ExpectedPixel> expected = expectedPixels(c.scene, c.applied);
  for (const auto& [i, j] : {std::pair{16, 16}, std::pair{8, 20}}) {
    const ExpectedPixel& e = expected[std::size_t(j) * c.scene.width + i];
    EXPECT_TRUE(e.onPlane && !e.nearEdge) << "pixel (" << i << ", " << j << ")";
  }
  checkOnBackend(c, GetParam());
}

TEST_P(IndependentPlaneBackend, PerObjectTruncation) { checkOnBackend(perObjectTruncationCase(), GetParam()); }

TEST_P(IndependentPlaneBackend, LegacyVertexLights) { checkOnBackend(legacyVertexLightsCase(), GetParam()); }

// SPEC 3.8's srp BRDF on the plane cases (the independent model's lobe): a
// medium highlight, so float32's conditioning at the peak stays far inside
// the 1e-3 of this comparison.
PlaneCase withSrp(PlaneCase c, double metallic, double smoothness) {
  c.scene.name += "-srp";
  c.scene.plane.srp = SrpMaterial{metallic, smoothness};
  return c;
}

TEST_P(IndependentPlaneBackend, OrthographicSrpBrdf) { checkOnBackend(withSrp(orthographicCase(), 0.35, 0.5), GetParam()); }

TEST_P(IndependentPlaneBackend, PerspectiveSrpBrdf) { checkOnBackend(withSrp(perspectiveCase(), 0.8, 0.6), GetParam()); }

INSTANTIATE_TEST_SUITE_P(EveryBackend, IndependentPlaneBackend,
                         ::testing::ValuesIn(backends::testing::allCombinations()),
                         backends::testing::combinationTestName);

}  // namespace
