#include "suite/bench/prepare_scenes.h"

#include "suite/bench/bench_scenes.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

namespace bench {
namespace {

using namespace lighting;

// A fixed-seed generator (splitmix64): the same scene on every machine.
class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}
  double uniform(double low, double high) {  // [low, high)
    state_ += 0x9e3779b97f4a7c15ull;
    std::uint64_t z = state_;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    z ^= z >> 31;
    return low + (high - low) * double(z >> 11) * 0x1.0p-53;
  }

 private:
  std::uint64_t state_;
};

std::string numbered(const char* prefix, int i) {
  std::string name(prefix);
  name += std::to_string(i);
  return name;
}

// Seen straight from above, orthographic, the square [-half, half]^2 exactly.
Camera topDownCamera(double half) {
  return Camera{{0, 10, 0}, {0, 0, 0}, {0, 0, -1}, Projection::Orthographic, 60, 2 * half, 0.1, 100};
}

Object box(const std::string& name, Vec3 at, double size) {
  Object o;
  o.name = name;
  o.mesh.type = MeshType::Box;
  o.mesh.boxSize = {size, size, size};
  o.transform.translate = at;
  o.albedo = {0.8, 0.7, 0.6};
  return o;
}

// A point or spot light (alternating) at a random place in the square
// [-half, half]^2, 0.5..2.5 above the ground, range in [rangeLow, rangeHigh).
Light randomLocalLight(Random& random, int i, double half, double rangeLow, double rangeHigh) {
  Light l;
  l.name = numbered("l", i);
  l.type = i % 2 == 0 ? LightType::Point : LightType::Spot;
  l.position = {random.uniform(-half, half), random.uniform(0.5, 2.5), random.uniform(-half, half)};
  l.direction = {0, -1, 0};
  l.range = random.uniform(rangeLow, rangeHigh);
  l.spotAngleDeg = 70;
  l.innerSpotAngleDeg = 50;
  l.color = {random.uniform(0.2, 1), random.uniform(0.2, 1), random.uniform(0.2, 1)};
  l.intensity = random.uniform(0.5, 3);
  return l;
}

// Half the side of a square holding `count` items at one per 4 square units.
double constantDensityHalf(int count) { return std::sqrt(4.0 * std::max(count, 1)) / 2; }

}  // namespace

Scene curveLightsScene(int lights, bool perObject) {
  Scene s;
  s.name = "curve-lights-" + std::to_string(lights) + (perObject ? "-per-object" : "-all-lights");
  s.sourcePath = "prepare_bench synthetic " + s.name;
  const double half = constantDensityHalf(lights) + 3;  // + the largest range: every light visible
  s.camera = topDownCamera(half);
  s.pipeline.lightsPerObject = perObject;
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 4; ++k)
      s.objects.push_back(box(numbered("box", i * 4 + k), {(i - 1.5) * 2.0, 0.25, (k - 1.5) * 2.0}, 0.5));
  Random random(0x11647u + std::uint64_t(lights));
  for (int i = 0; i < lights; ++i) s.lights.push_back(randomLocalLight(random, i, half - 3, 1, 3));
  return s;
}

Scene curveObjectsScene(int objects) {
  constexpr int kGrid = 8;
  constexpr double kHalf = 20, kSpacing = 2 * kHalf / kGrid;
  Scene s;
  s.name = "curve-objects-" + std::to_string(objects);
  s.sourcePath = "prepare_bench synthetic " + s.name;
  s.camera = topDownCamera(kHalf + 4);
  s.pipeline.lightsPerObject = true;
  for (int i = 0; i < kGrid; ++i) {
    for (int k = 0; k < kGrid; ++k) {
      Light l;
      l.name = numbered("p", i * kGrid + k);
      l.type = LightType::Point;
      l.position = {-kHalf + (i + 0.5) * kSpacing, 1.0, -kHalf + (k + 0.5) * kSpacing};
      l.range = 4;
      l.color = {0.5 + 0.5 * (i % 2), 0.5 + 0.5 * (k % 2), 1.0};
      s.lights.push_back(l);
    }
  }
  Random random(0x0b1ec75u + std::uint64_t(objects));
  for (int o = 0; o < objects; ++o)
    s.objects.push_back(box(numbered("box", o), {random.uniform(-kHalf, kHalf), 0.25, random.uniform(-kHalf, kHalf)}, 0.5));
  return s;
}

Scene shadowMaskScene(int lights) {
  Scene s;
  s.name = "shadow-mask-" + std::to_string(lights);
  s.sourcePath = "prepare_bench synthetic " + s.name;
  const double half = constantDensityHalf(lights);
  s.camera = topDownCamera(half + 2);
  Light sun;
  sun.name = "sun";
  sun.type = LightType::Directional;
  sun.direction = glm::normalize(Vec3(0.3, -1, 0.2));
  sun.mode = LightMode::Mixed;
  sun.shadows = true;
  s.lights.push_back(sun);
  Random random(0x5ad0u + std::uint64_t(lights));
  for (int i = 1; i < lights; ++i) {
    Light l = randomLocalLight(random, i, half, 0.5, 2);
    l.mode = LightMode::Mixed;
    l.shadows = true;
    l.shadowStrength = 1;
    s.lights.push_back(l);
  }
  return s;
}

// As render_bench's sixtyFourLightsOverAField (the same geometry, so the CPU
// and the draw benchmarks of `lights64-1280x720` share a scene).
Scene sixtyFourLightsScene(bool perObject) {
  // The frame benchmarks' field (bench_scenes.h), so CPU and GPU time the same scene.
  FieldSpec spec;
  spec.mode = perObject ? FrameMode::PerObject : FrameMode::AllLights;
  return fieldScene(spec, perObject ? "lights64-1280x720-per-object" : "lights64-1280x720-all");
}

}  // namespace bench
