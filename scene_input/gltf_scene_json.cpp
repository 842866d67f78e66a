#include "scene_input/gltf_scene_json.h"

#include "lighting/scene_words.h"

namespace scene_input {

using namespace lighting;  // the model this folder reads scenes into
namespace {

using Json = nlohmann::ordered_json;

Json vec3(const Vec3& v) { return Json::array({v.x, v.y, v.z}); }

Json cameraJson(const Camera& camera) {
  Json out = {{"position", vec3(camera.position)}, {"target", vec3(camera.target)}, {"up", vec3(camera.up)}};
  out["projection"] = wordOf(kProjectionWords, camera.projection);
  if (camera.projection == Projection::Perspective) out["fov_y_deg"] = camera.fovYDeg;
  else out["height"] = camera.orthoHeight;
  out["near"] = camera.nearPlane;
  out["far"] = camera.farPlane;
  return out;
}

// The keys a bare import's light can carry: glTF's, and the range it was
// given (SPEC 2.1: what glTF has no word for keeps the scene format's default).
Json lightJson(const Light& light) {
  Json out = {{"name", light.name}, {"type", wordOf(kLightTypeWords, light.type)}};
  if (light.type != LightType::Directional) out["position"] = vec3(light.position);
  if (light.type != LightType::Point) out["direction"] = vec3(light.direction);
  if (light.type != LightType::Directional) out["range"] = light.range;
  if (light.type == LightType::Spot) {
    out["spot_angle_deg"] = light.spotAngleDeg;
    if (light.innerSpotAngleDeg) out["inner_spot_angle_deg"] = *light.innerSpotAngleDeg;
  }
  out["color"] = vec3(light.color);
  out["intensity"] = light.intensity;
  return out;
}

}  // namespace

Json bareGltfSceneJson(const Scene& scene, const std::string& gltfPath) {
  Json lights = Json::array();
  for (const Light& light : scene.lights) lights.push_back(lightJson(light));
  return Json{{"lightcts", 1},
              {"name", scene.name},
              {"description", scene.description},
              {"image", {{"width", scene.image.width}, {"height", scene.image.height}}},
              {"camera", cameraJson(scene.camera)},
              {"ambient", vec3(scene.ambient)},
              {"imports", Json::array({Json{{"gltf", gltfPath}, {"lights", false}}})},
              {"objects", Json::array()},
              {"lights", lights}};
}

}  // namespace scene_input
