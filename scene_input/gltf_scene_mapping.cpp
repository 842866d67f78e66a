#include "scene_input/gltf_scene_mapping.h"

#include "lighting/default_rig.h"
#include "scene_input/look_at.h"
#include "scene_input/scene_loader.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

namespace scene_input {

using namespace lighting;  // the model this folder reads scenes into

namespace {

// A bare file's light range when the content has no extent (a single point).
constexpr double kSmallestBareRange = 1;
// Beyond the farthest corner by this factor, so nothing is clipped at far.
constexpr double kFarPlaneMargin = 1.01;

double farthestCornerDistance(const Vec3& from, const GltfContent& content) {
  double farthest = 0;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 p((corner & 1) ? content.boundsMax.x : content.boundsMin.x,
                 (corner & 2) ? content.boundsMax.y : content.boundsMin.y,
                 (corner & 4) ? content.boundsMax.z : content.boundsMin.z);
    farthest = std::max(farthest, glm::length(p - from));
  }
  return farthest;
}

// A perspective camera (60 degrees) looking at the centre of the content
// from the front (+Z) and a little above and to the right, at a distance
// that fits its bounding sphere.
Camera framingCamera(const GltfContent& content) {
  const Vec3 centre = (content.boundsMin + content.boundsMax) * 0.5;
  const double radius = std::max(0.5 * glm::length(content.boundsMax - content.boundsMin), 1e-3);
  Camera camera;
  camera.projection = Projection::Perspective;
  camera.fovYDeg = 60;
  const double distance = radius / std::sin(camera.fovYDeg * std::numbers::pi / 360) * 1.05;
  camera.position = centre + glm::normalize(Vec3(0.5, 0.5, 1)) * distance;
  camera.target = centre;
  camera.up = Vec3(0, 1, 0);
  camera.nearPlane = std::max(distance - 1.5 * radius, distance * 1e-3);
  camera.farPlane = distance + 1.5 * radius;
  return camera;
}

}  // namespace

Object sceneObject(const ImportedPrimitive& primitive, const std::optional<Object>& material, Profile profile) {
  Object object = material.value_or(Object{});
  object.name = primitive.name;
  object.mesh.type = MeshType::Imported;
  object.mesh.imported = primitive.mesh;
  if (material) return object;
  // SPEC 2.1's mapping: glTF's roughness is URP's perceptual roughness.
  object.albedo = primitive.baseColor;
  if (profile == Profile::Legacy) return object;  // diffuse only: lambert with that albedo
  object.brdf = Brdf::Srp;
  object.metallic = primitive.metallic;
  object.smoothness = 1 - primitive.roughness;
  return object;
}

Light sceneLight(const ImportedLight& in, const GltfContent& content, const LightDefaults* defaults,
                 std::optional<double> bareRange, const std::string& context) {
  Light light;
  light.name = in.name;
  light.type = in.type;
  light.position = in.position;
  light.direction = in.direction;
  light.color = in.color;
  light.intensity = in.intensity;
  light.spotAngleDeg = in.spotAngleDeg;
  light.innerSpotAngleDeg = in.innerSpotAngleDeg;
  const std::optional<double> defaultRange = defaults ? defaults->range : std::nullopt;
  if (in.range) light.range = *in.range;
  else if (defaultRange) light.range = *defaultRange;
  else if (bareRange) light.range = *bareRange;
  else if (in.type != LightType::Directional)
    throwAsSceneError(GltfError(content.file, in.pointer,
                                "the light '" + in.name + "' has no range and the import gives no light_defaults.range",
                                content.positionOf(in.pointer)),
                      context);
  if (!defaults) return light;
  if (defaults->mode) light.mode = *defaults->mode;
  if (defaults->shadows) light.shadows = *defaults->shadows;
  if (defaults->shadowStrength) light.shadowStrength = *defaults->shadowStrength;
  if (defaults->bakeFalloff) light.bakeFalloff = *defaults->bakeFalloff;
  if (defaults->perLight) defaults->perLight(light);
  return light;
}

std::optional<Camera> sceneCamera(const ImportedCamera& in, const GltfContent& content) {
  Camera camera;
  camera.position = in.position;
  camera.target = in.position + in.forward;
  camera.up = in.up;
  camera.nearPlane = in.znear;
  if (in.perspective) {
    camera.projection = Projection::Perspective;
    camera.fovYDeg = in.yfovRad * 180 / std::numbers::pi;
  } else {
    camera.projection = Projection::Orthographic;
    camera.orthoHeight = 2 * in.ymag;
  }
  if (!(camera.nearPlane > 0)) camera.nearPlane = 1e-3 * in.zfar.value_or(1.0);  // glTF allows 0 for orthographic
  camera.farPlane = in.zfar.value_or(farthestCornerDistance(in.position, content) * kFarPlaneMargin);
  if (!(camera.farPlane > camera.nearPlane)) camera.farPlane = camera.nearPlane * 1000;
  if (lookAtProblem(camera.position, camera.target, camera.up)) return std::nullopt;
  return camera;
}

void lightByDefaultRig(Scene& scene, const GltfContent& content, bool takeAmbient) {
  DefaultRig rig = defaultRig(content.boundsMin, content.boundsMax, scene.camera);
  for (Light& light : rig.lights) scene.lights.push_back(std::move(light));
  if (takeAmbient) scene.ambient = rig.ambient;
}

Scene bareGltfScene(const std::string& file) {
  GltfImportRequest request;
  request.file = file;
  GltfContent content;
  const std::string context = "read as a bare glTF scene";
  try {
    content = importGltf(request);
  } catch (const GltfError& error) {
    throwAsSceneError(error, context);
  }
  Scene scene;
  scene.name = std::filesystem::path(file).stem().string();
  scene.description = "the glTF file " + std::filesystem::path(file).filename().string() + " alone";
  std::optional<Camera> camera;
  for (const auto& c : content.cameras)
    if (c && !camera) camera = sceneCamera(*c, content);
  scene.camera = camera ? *camera : framingCamera(content);
  const double diagonal = std::max(glm::length(content.boundsMax - content.boundsMin), kSmallestBareRange);
  for (const ImportedPrimitive& primitive : content.primitives)
    scene.objects.push_back(sceneObject(primitive, std::nullopt, scene.pipeline.profile));
  for (const ImportedLight& in : content.lights)
    scene.lights.push_back(sceneLight(in, content, nullptr, diagonal, context));
  scene.warnings = std::move(content.warnings);
  // SPEC 2.1: content without lights gets the default rig, not a black image.
  if (content.lights.empty()) {
    lightByDefaultRig(scene, content, true);
    scene.warnings.push_back(file +
                             ": the file has no KHR_lights_punctual lights: it is lit by the default rig "
                             "(docs/scene-format.md; `lightcts lights --scene FILE --scene-json` prints it as a scene file)");
  }
  return scene;
}

void throwAsSceneError(const GltfError& error, const std::string& context) {
  throw SceneLoadError(SceneError{error.file(), error.pointer(), error.where().line, error.where().column,
                                  error.message() + " (" + context + ")"});
}

}  // namespace scene_input
