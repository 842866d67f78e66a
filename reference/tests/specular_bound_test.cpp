// The specular lobe's bound (specular_bound.h) against float32 evaluations of
// SPEC 3.8: every float evaluation from float inputs within the stated input
// errors must land inside [value - bound, value + bound]. The float side is
// written here with C++ floats (correctly rounded, so it is one admissible
// implementation, not the worst); it checks that the bound holds and follows
// the peak's conditioning, not that it is tight.
#include "reference/specular_bound.h"

#include "lighting/brdf.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <random>

namespace reference {
namespace {

using glm::vec3;

float saturateF(float x) { return std::clamp(x, 0.0f, 1.0f); }

// SPEC 3.8 in float32, step for step as shaders/lighting.glsl does it.
float floatLobe(vec3 N, vec3 V, vec3 L, float smoothness) {
  const float roughness = (1.0f - smoothness) * (1.0f - smoothness);
  const vec3 h = L + V;
  const vec3 H = h * (1.0f / std::sqrt(std::max(glm::dot(h, h), 1.17549435e-38f)));
  const float nh = saturateF(glm::dot(N, H)), lh = saturateF(glm::dot(L, H));
  const float nh2 = nh * nh, lh2 = lh * lh;
  const float r2 = roughness * roughness;
  const float d = nh2 * (r2 - 1.0f) + 1.00001f;
  return r2 / (d * d * std::max(0.1f, lh2) * (roughness * 4.0f + 2.0f));
}

vec3 toFloat(const Vec3& v) { return vec3(float(v.x), float(v.y), float(v.z)); }

TEST(SpecularBound, HoldsForFloatEvaluationsAroundThePeak) {
  std::mt19937 random(17);
  std::uniform_real_distribution<double> angle(0.0, 0.05);  // radians off the peak
  std::uniform_real_distribution<double> turn(0.0, 6.283185307179586);
  const double u = 0x1p-24;
  const LobeInputErrors errors{{7 * u, 5 * u}, {2 * u, 2 * u}, {2 * u, 2 * u}};
  int checked = 0;
  for (double smoothness : {0.0, 0.5, 0.9, 0.97}) {
    for (int k = 0; k < 2000; ++k) {
      const Vec3 N(0, 1, 0);
      const double a = angle(random), t = turn(random), b = angle(random);
      const Vec3 V = glm::normalize(Vec3(std::sin(a) * std::cos(t), std::cos(a), std::sin(a) * std::sin(t)));
      const Vec3 L = glm::normalize(Vec3(-std::sin(b) * std::cos(t + 0.3), std::cos(b), -std::sin(b) * std::sin(t + 0.3)));
      const SpecularBound s = specularWithBound(N, V, L, smoothness, errors);
      const double f = floatLobe(toFloat(N), toFloat(V), toFloat(L), float(smoothness));
      ASSERT_LE(std::abs(f - s.value), s.errorBound)
          << "smoothness " << smoothness << " value " << s.value << " float " << f;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 8000);
}

TEST(SpecularBound, FollowsTheConditioningOfThePeak) {
  // At the peak of smoothness 0.9, d = 1.1e-4: the constant 1.00001 alone is
  // off by 1.4e-8 in float32, 1.2e-4 of d, 2.5e-4 of d2; the bound must be at
  // least that relative, and the float evaluation must sit inside it. At
  // most 10 %: each operation's rounding counts a whole ULP (either
  // neighbour; tolerance_model.h, kStepRoundoff), twice the 5 % of one
  // rounding to nearest.
  const Vec3 up(0, 1, 0);
  const double u = 0x1p-24;
  const LobeInputErrors errors{{7 * u, 5 * u}, {2 * u, 2 * u}, {2 * u, 2 * u}};
  const SpecularBound s = specularWithBound(up, up, up, 0.9, errors);
  EXPECT_GT(s.errorBound / s.value, 2.4e-4);
  EXPECT_LT(s.errorBound / s.value, 0.10);
  const double f = floatLobe(vec3(0, 1, 0), vec3(0, 1, 0), vec3(0, 1, 0), 0.9f);
  EXPECT_GT(std::abs(f - s.value), 1e-4 * s.value) << "float32 is off at the peak, as SPEC 3.8 says";
  EXPECT_LE(std::abs(f - s.value), s.errorBound);
  // Smoothness 1: exactly 0 on both sides.
  const SpecularBound one = specularWithBound(up, up, up, 1.0, errors);
  EXPECT_EQ(one.value, 0.0);
  EXPECT_EQ(one.errorBound, 0.0);
}

TEST(SpecularBound, LOppositeVLeavesHUndetermined) {
  const Vec3 up(0, 1, 0);
  const LobeInputErrors errors{{1e-6, 1e-6}, {1e-6, 1e-6}, {1e-6, 1e-6}};
  const SpecularBound s = specularWithBound(up, up, -up, 0.5, errors);
  EXPECT_TRUE(s.halfVectorAmbiguous);
  // Any unit H is admissible: up to the peak value r2 / ((r2 + 1e-5)^2 * 0.1 * k).
  const double r = 0.25, r2 = r * r;
  EXPECT_GE(s.value + s.errorBound, r2 / ((r2 + 1e-5) * (r2 + 1e-5) * 0.1 * (4 * r + 2)) * (1 - 1e-6));
}

}  // namespace
}  // namespace reference
