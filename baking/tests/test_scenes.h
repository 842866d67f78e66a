// Small scenes for the baker's tests, built in code (the lights by
// lighting/tests/light_builders.h).
#pragma once

#include "baking/bake.h"
#include "lighting/scene.h"
#include "lighting/tests/light_builders.h"

#include <filesystem>
#include <string>

namespace baking::testing {

using lighting::Light;
using lighting::LightMode;
using lighting::LightType;
using lighting::Object;
using lighting::Scene;
using lighting::Vec3;
using lighting::testing::directionalLight;
using lighting::testing::pointLight;

inline Object lightmappedPlane(double sizeX, double sizeZ, int resolution) {
  Object o;
  o.name = "floor";
  o.mesh.type = lighting::MeshType::Plane;
  o.mesh.planeSizeX = sizeX;
  o.mesh.planeSizeZ = sizeZ;
  o.isStatic = true;
  o.lightmapResolution = resolution;
  return o;
}

inline Object box(Vec3 size, Vec3 translate) {
  Object o;
  o.name = "box";
  o.mesh.type = lighting::MeshType::Box;
  o.mesh.boxSize = size;
  o.transform.translate = translate;
  return o;
}

inline Light mixedShadowed(Vec3 position, double range, double intensity) {
  Light l = pointLight(position, range, intensity, LightMode::Mixed);
  l.shadows = true;
  l.shadowStrength = 1;
  return l;
}

// Bakes without touching any cache.
inline std::shared_ptr<const lighting::BakedLighting> bakeUncached(const Scene& scene, int threads = 0,
                                                                   bool mutantLegacyFalloff = false) {
  BakeOptions options;
  options.useCache = false;
  options.threads = threads;
  options.mutantLegacyFalloff = mutantLegacyFalloff;
  return bakeScene(*lighting::prepareScene(scene), options);
}

// Texel (i, j) of a map, channel c (layout of lighting/baked_lighting.h).
inline float texel(const lighting::TexelMap& map, int i, int j, int c) {
  return map.texels[(std::size_t(j) * std::size_t(map.resolution) + std::size_t(i)) * 4 + std::size_t(c)];
}

}  // namespace baking::testing
