// SPEC 1's lookAt(position, target, up) and when it has no basis: what the
// scene reader checks of a camera and a keyframe, and what makes a glTF
// camera unusable (scene_input/gltf_scene_mapping.h).
#pragma once

#include "lighting/scene.h"

#include <optional>

namespace scene_input {

// `v` scaled to unit length, or nullopt for the zero vector.
std::optional<lighting::Vec3> unitVector(const lighting::Vec3& v);

enum class LookAtProblem { SamePoint, UpParallel };

// A view direction (target - position) is needed, and an up that is not along it.
std::optional<LookAtProblem> lookAtProblem(const lighting::Vec3& position, const lighting::Vec3& target,
                                           const lighting::Vec3& up);

}  // namespace scene_input
