// SPEC 2.1's mapping of glTF content onto the model, in one place: what an
// imported primitive, KHR_lights_punctual light and camera become in a
// scene, what an import's light_defaults give its lights, how the default
// rig lights content, and what a bare glTF file is as a scene. The scene
// reader (scene_loader.cpp) reads the scene format, with an import's
// options, and hands them here typed; the importer (gltf_import.h) reads the
// file.
#pragma once

#include "lighting/scene.h"
#include "scene_input/gltf_import.h"

#include <functional>
#include <optional>
#include <string>

namespace scene_input {

// An import's `light_defaults` (SPEC 2.1), read once by the scene reader:
// what glTF has no word for. A cookie and a shadow map depend on the
// light's type, so the reader reads them for each light (`perLight`).
struct LightDefaults {
  std::optional<double> range;
  std::optional<lighting::LightMode> mode;
  std::optional<bool> shadows;
  std::optional<double> shadowStrength;
  std::optional<lighting::BakeFalloff> bakeFalloff;
  std::function<void(lighting::Light&)> perLight;  // after the others are set; null: nothing per light
};

// A primitive as a scene object: `material` instead of the file's when the
// import gives one, else SPEC 2.1's mapping (base colour as albedo; in the
// srp profile metallic, and smoothness = 1 - roughness).
lighting::Object sceneObject(const ImportedPrimitive& primitive, const std::optional<lighting::Object>& material,
                             lighting::Profile profile);

// A light as a scene light. Its range is the file's, else the defaults',
// else `bareRange`; a point or spot light with none is a GltfError at the
// light, raised as a scene error with `context` (throwAsSceneError).
lighting::Light sceneLight(const ImportedLight& in, const GltfContent& content, const LightDefaults* defaults,
                           std::optional<double> bareRange, const std::string& context);

// A camera as the model's: perspective with its yfov, or orthographic with
// height 2 * ymag; without zfar, a far plane just beyond the farthest corner
// of the content. nullopt when its up lies along its view.
std::optional<lighting::Camera> sceneCamera(const ImportedCamera& in, const GltfContent& content);

// SPEC 2.1's default rig for `content` seen from the scene's camera: its
// lights appended to the scene's, and its ambient where `takeAmbient`.
void lightByDefaultRig(lighting::Scene& scene, const GltfContent& content, bool takeAmbient);

// SPEC 2.1's bare glTF file: the import alone with the scene format's
// defaults (image 128x128, srp forward, no ambient) and docs/scene-format.md's
// choices: the file's first camera on a node, else a perspective camera that
// frames the content; a light without a range reaches the content's
// diagonal; content without lights is lit by the default rig, with a warning.
lighting::Scene bareGltfScene(const std::string& file);

// A GltfError as the scene error it is reported as: the glTF file, its JSON
// path, the line and column the importer found, and `context` (which scene
// imported it, or "read as a bare glTF scene").
[[noreturn]] void throwAsSceneError(const GltfError& error, const std::string& context);

}  // namespace scene_input
