// SPEC 2.1's default rig: the lights a glTF file without KHR_lights_punctual
// lights gets when read as a scene (or when an import asks for it), placed
// from the content's bounds and the camera that views it, so a model can be
// checked without a scene written around it (as model-viewer and Filament's
// viewer light any model out of the box). docs/scene-format.md ("The default
// rig") gives the placement; `lightcts lights --scene-json` prints it in a scene file.
#pragma once

#include "lighting/scene.h"

#include <vector>

namespace lighting {

struct DefaultRig {
  // A directional key light, a point fill light and a spot rim light, in
  // that order, named rig-directional, rig-point and rig-spot.
  std::vector<Light> lights;
  Vec3 ambient;  // small, so no face of the content is black
};

// The rig for content within [boundsMin, boundsMax] (world space) seen by
// `camera`: the point and spot lights stand on the camera's side of the
// content, above it, with ranges that reach the far side of its bounding
// sphere; the spot's cone holds the whole sphere; the directional light
// comes from above, over the camera's shoulder.
DefaultRig defaultRig(const Vec3& boundsMin, const Vec3& boundsMax, const Camera& camera);

}  // namespace lighting
