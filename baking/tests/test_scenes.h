// Small scenes for the baker's tests, built in code. Lights are built
// directly (not through the loader), so directions are normalised here.
#pragma once

#include "baking/bake.h"
#include "lighting/scene.h"

#include <glm/geometric.hpp>

#include <filesystem>
#include <string>

namespace baking::testing {

using lighting::Light;
using lighting::LightMode;
using lighting::LightType;
using lighting::Object;
using lighting::Scene;
using lighting::Vec3;

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

inline Light pointLight(Vec3 position, double range, LightMode mode, Vec3 color = {1, 1, 1}, double intensity = 1) {
  Light l;
  l.name = "point";
  l.type = LightType::Point;
  l.position = position;
  l.range = range;
  l.mode = mode;
  l.color = color;
  l.intensity = intensity;
  return l;
}

inline Light mixedShadowed(Vec3 position, double range, double intensity) {
  Light l = pointLight(position, range, LightMode::Mixed, {1, 1, 1}, intensity);
  l.shadows = true;
  l.shadowStrength = 1;
  return l;
}

inline Light directionalLight(Vec3 direction, LightMode mode, Vec3 color, double intensity) {
  Light l;
  l.name = "sun";
  l.type = LightType::Directional;
  l.direction = glm::normalize(direction);
  l.mode = mode;
  l.color = color;
  l.intensity = intensity;
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
