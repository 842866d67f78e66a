// Lights and frames for the tests of the model and of what is built on it
// (reference, baking): each builder sets what its arguments say (intensity 1
// and colour white unless given) and leaves every other field at the scene
// format's default (SPEC 2), so a test names only what it is about.
#pragma once

#include "lighting/frame.h"
#include "lighting/scene.h"

#include <glm/glm.hpp>

#include <utility>

namespace lighting::testing {

inline Light pointLight(Vec3 position, double range = 1, double intensity = 1, LightMode mode = LightMode::Realtime,
                        Vec3 color = {1, 1, 1}) {
  Light l;
  l.type = LightType::Point;
  l.position = position;
  l.range = range;
  l.intensity = intensity;
  l.mode = mode;
  l.color = color;
  return l;
}

// `direction`, the way the light travels, is normalised as the loader does.
inline Light directionalLight(double intensity = 1, Vec3 direction = {0, -1, 0}, LightMode mode = LightMode::Realtime,
                              Vec3 color = {1, 1, 1}) {
  Light l;
  l.type = LightType::Directional;
  l.direction = glm::normalize(direction);
  l.intensity = intensity;
  l.mode = mode;
  l.color = color;
  return l;
}

// Frame `index` of the scene, prepared as every renderer prepares it.
inline Frame frameOf(Scene scene, int index = 0) { return prepareFrame(prepareScene(std::move(scene)), index); }

}  // namespace lighting::testing
