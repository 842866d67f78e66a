#include "lighting/frame.h"

#include <glm/geometric.hpp>

#include <stdexcept>

namespace lighting {
namespace {

// SPEC 5.2: the world-space sphere around the transformed centre of the mesh's
// local bounding box, radius scale * half the box diagonal.
BoundingSphere worldBounds(const Mesh& mesh, const ObjectTransform& transform) {
  const Vec3 centre = (mesh.boundsMin + mesh.boundsMax) * 0.5;
  return {transform.applyToPoint(centre), transform.scale * 0.5 * glm::length(mesh.boundsMax - mesh.boundsMin)};
}

ShaderFeatures featuresOf(const Frame& frame) {
  const Scene& scene = frame.scene();
  ShaderFeatures f;
  f.perObjectLists = Frame::perObjectListsEnabled(scene);
  const bool deferred = scene.pipeline.path == RenderPath::Deferred;
  // Deferred lights every kept light per pixel: no vertex lights (SPEC 3.7).
  f.vertexLights = scene.pipeline.profile == Profile::Legacy && !deferred;
  f.ldr8Buffer = deferred && scene.pipeline.deferredBuffer == DeferredBuffer::Ldr8;
  f.ambient = scene.ambient != Vec3(0.0);
  auto note = [&](int lightIndex) {
    const Light& l = scene.lights[lightIndex];
    f.directionalLights |= l.type == LightType::Directional;
    f.pointLights |= l.type == LightType::Point;
    f.spotLights |= l.type == LightType::Spot;
  };
  for (int i : frame.selection.packed.directional) note(i);
  for (int i : frame.selection.packed.other) note(i);
  // The shadow mask attenuates only on objects that have one (SPEC 3.5).
  bool anyMask = false;
  for (const Object& o : scene.objects) anyMask |= o.hasLightmap();
  bool anyChannel = false;
  for (int c : frame.prepared->shadowMask.channelOfLight) anyChannel |= c >= 0;
  f.shadowMask = anyMask && anyChannel;
  f.lightmap = anyMask;
  for (const Object& o : scene.objects) f.specularBrdf |= o.brdf == Brdf::Srp;
  f.cookies = frame.cookies.any();
  f.shadowMaps = frame.shadows.any();
  f.cookieTextures = int(frame.cookies.textureLights.size());
  f.cookieCubes = int(frame.cookies.cubeLights.size());
  f.shadowMapTextures = int(frame.shadows.maps.size());
  f.shadowMapCubes = int(frame.shadows.cubes.size());
  for (const ShadowProjection& map : frame.shadows.maps) f.shadowTent |= map.spec.filter == ShadowFilter::Tent3x3;
  return f;
}

}  // namespace

std::shared_ptr<const PreparedScene> prepareScene(Scene scene) {
  auto prepared = std::make_shared<PreparedScene>();
  prepared->objects.reserve(scene.objects.size());
  for (const Object& object : scene.objects) {
    ObjectGeometry g;
    g.mesh = buildMesh(object.mesh);
    g.transform = objectTransform(object.transform);
    g.bounds = worldBounds(g.mesh, g.transform);
    prepared->objects.push_back(std::move(g));
  }
  prepared->shadowMask = assignShadowMaskChannels(scene);
  prepared->scene = std::move(scene);
  return prepared;
}

bool PreparedScene::needsBake() const {
  for (const Object& o : scene.objects)
    if (o.hasLightmap()) return true;
  return false;
}

const ObjectBake* PreparedScene::bakeOf(int object) const {
  if (!scene.objects[object].hasLightmap()) return nullptr;
  if (!baked)
    throw std::logic_error("scene '" + scene.name +
                           "' has lightmaps but was prepared without a bake (use baking::prepareBakedScene)");
  return &baked->objects[object];
}

bool Frame::perObjectListsEnabled(const Scene& scene) {
  // Deferred draws light volumes, not objects: per-object lists do not apply.
  if (scene.pipeline.path == RenderPath::Deferred) return false;
  return scene.pipeline.profile == Profile::Legacy || scene.pipeline.lightsPerObject;
}

ObjectLights Frame::lightsForObject(int object) const {
  ObjectLights lights;
  const PackedLights& packed = selection.packed;
  if (!perObjectListsEnabled(scene())) {
    lights.perPixel = packed.directional;
    lights.perPixel.insert(lights.perPixel.end(), packed.other.begin(), packed.other.end());
    return lights;
  }
  const ObjectLightList& list = objectLists[object];
  if (scene().pipeline.profile == Profile::Srp) {
    // srp lists hold point and spot lights; directional lights always apply.
    lights.perPixel = packed.directional;
    for (int p : list.indices) lights.perPixel.push_back(packed.other[p]);
    return lights;
  }
  // Legacy: list positions 0-3 per pixel, 4-7 per vertex (SPEC 4).
  constexpr int kLegacyPixelLights = 4;
  for (int k = 0; k < int(list.indices.size()); ++k)
    (k < kLegacyPixelLights ? lights.perPixel : lights.perVertex).push_back(packed.other[list.indices[k]]);
  return lights;
}

ObjectLights Frame::idealLightsForObject() const {
  ObjectLights lights;
  for (int i = 0; i < int(scene().lights.size()); ++i)
    if (!isBakedLight(scene(), prepared->shadowMask, i)) lights.perPixel.push_back(i);
  return lights;
}

Frame prepareFrame(std::shared_ptr<const PreparedScene> prepared, int index) {
  Frame frame;
  frame.prepared = std::move(prepared);
  frame.index = index;
  const Scene& scene = frame.scene();
  frame.view = cameraViewForFrame(scene, index);
  frame.selection = selectVisibleLights(scene, frame.view, frame.prepared->shadowMask);
  if (Frame::perObjectListsEnabled(scene)) {
    std::vector<BoundingSphere> bounds;
    for (const ObjectGeometry& g : frame.prepared->objects) bounds.push_back(g.bounds);
    frame.objectLists = buildObjectLightLists(scene, frame.selection, bounds);
  }
  frame.cookies = assignCookieSlots(scene, frame.selection);
  frame.shadows = assignShadowSlots(scene, frame.selection);
  frame.features = featuresOf(frame);
  return frame;
}

}  // namespace lighting
