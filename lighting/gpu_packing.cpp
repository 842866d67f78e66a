#include "lighting/gpu_packing.h"

#include "lighting/cookie_packing.h"
#include "lighting/light_math.h"
#include "lighting/shadow_packing.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace lighting {
namespace {

GpuVec4 vec4(const Vec3& v, double w) {
  return {float(v.x), float(v.y), float(v.z), float(w)};
}

}  // namespace

GpuMat4 toGpuMat4(const glm::dmat4& m) {
  GpuMat4 out;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) out.m[c * 4 + r] = float(m[c][r]);
  return out;
}

GpuLight packGpuLight(const Frame& frame, int lightIndex, double weight) {
  const Scene& scene = frame.scene();
  const Light& light = scene.lights[lightIndex];
  GpuLight g;
  const bool directional = light.type == LightType::Directional;
  if (directional) {
    g.position = vec4(-light.direction, 0.0);
    g.color = vec4(light.finalColor() * weight, 0.0);
  } else {
    g.position = vec4(light.position - frame.view.camera.position, 1.0);
    g.color = vec4(light.finalColor() * weight, inverseRangeSquared(light.range));
  }
  // w: the light's cookie slot (SPEC 3.10), -1 without one (shaders/cookies.glsl).
  g.spotDirection = vec4(-light.direction, double(cookieBlockSlot(frame, lightIndex)));
  const SpotFactors spot = lightSpotFactors(light, scene.pipeline.profile);
  // z: the light's shadow, a mixed light's mask channel (SPEC 3.5) or a real-time
  // light's shadow block slot after them (SPEC 3.9, shadow_packing.h); w: the
  // mask's strength (a shadow slot carries its own).
  const int channel = frame.prepared->shadowMask.channelOfLight[lightIndex];
  const int shadowSlot = shadowBlockSlot(frame, lightIndex);
  const int shadow = channel >= 0 ? channel : shadowSlot >= 0 ? kShadowSlotBase + shadowSlot : -1;
  g.spotAngles = {float(spot.a), float(spot.b), float(shadow), channel >= 0 ? float(light.shadowStrength) : 0.0f};
  return g;
}

GpuFrameBlock packFrameBlock(const Frame& frame, const DeviceGrid& grid) {
  GpuFrameBlock block;
  block.viewProjection = toGpuMat4(frame.view.cameraRelativeViewProjection());
  block.ambient = vec4(frame.scene().ambient, 0.0);
  block.cameraPosition = vec4(frame.view.camera.position, 1.0);  // test-only (the absolute-coordinates mutants)
  const bool orthographic = frame.view.camera.projection == Projection::Orthographic;
  block.view = vec4(-frame.view.forward, orthographic ? 1.0 : 0.0);
  const PackedLights& packed = frame.selection.packed;
  const bool legacy = frame.scene().pipeline.profile == Profile::Legacy;
  block.lightCounts = {int(packed.directional.size()), int(packed.other.size()), legacy ? 1 : 0, frame.clusters ? 1 : 0};
  block.rasterGrid = {float(frame.view.width), float(frame.view.height), std::ldexp(1.0f, grid.subPixelBits),
                      grid.framebufferYAgainstNdc};
  block.filterGrid = {std::ldexp(1.0f, grid.subTexelBits), 0.0f, 0.0f, 0.0f};
  if (frame.clusters) {
    const ClusterGrid& grid = frame.clusters->grid;
    block.clusterGrid = {grid.tilesX, grid.tilesY, grid.slices, grid.tileSize};
    block.clusterScreen = {float(frame.view.width), float(frame.view.height), 0.0f, 0.0f};
    block.clusterForward = vec4(frame.view.forward, 0.0);
    block.clusterSlicing = {float(grid.sliceScale()), float(grid.sliceBias()), grid.exponential ? 1.0f : 0.0f,
                            float(grid.nearDepth)};
  }
  for (std::size_t i = 0; i < packed.directional.size(); ++i)
    block.directionalLights[i] = packGpuLight(frame, packed.directional[i], packed.directionalWeight[i]);
  for (std::size_t i = 0; i < packed.other.size(); ++i)
    block.otherLights[i] = packGpuLight(frame, packed.other[i], packed.otherWeight[i]);
  return block;
}

std::vector<std::uint32_t> packClusterTexels(const LightClusters& clusters) {
  const std::size_t headers = clusters.first.size();
  const std::size_t total = headers + clusters.lights.size();
  if (total > (std::size_t(1) << (32 - kClusterCountBits)))
    throw std::length_error("light clusters: " + std::to_string(total) + " texels, more than a header can address");
  std::vector<std::uint32_t> texels;
  texels.reserve(total);
  for (std::size_t c = 0; c < headers; ++c)
    texels.push_back(std::uint32_t((headers + clusters.first[c]) << kClusterCountBits) | clusters.count[c]);
  texels.insert(texels.end(), clusters.lights.begin(), clusters.lights.end());
  return texels;
}

std::vector<std::uint32_t> packFrameClusterTexels(const Frame& frame) {
  return frame.clusters ? packClusterTexels(*frame.clusters) : std::vector<std::uint32_t>{0};
}

GpuObjectBlock packObjectBlock(const Frame& frame, int object) {
  const Object& obj = frame.scene().objects[object];
  const ObjectGeometry& geometry = frame.prepared->objects[object];
  const ObjectTransform& t = geometry.transform;
  glm::dmat4 model(t.rotation * t.scale);
  const Vec3 translate = t.translate - frame.view.camera.position;
  model[3] = glm::dvec4(translate, 1.0);

  GpuObjectBlock block;
  block.model = toGpuMat4(model);
  block.normalMatrix = toGpuMat4(glm::dmat4(t.rotation));
  block.albedo = vec4(obj.albedo, 1.0);
  const bool srp = obj.brdf == Brdf::Srp;
  block.material = {float(srp ? obj.metallic : 0.0), float(srp ? obj.smoothness : 0.0), srp ? 1.0f : 0.0f, 0.0f};
  const bool hasMap = obj.hasLightmap();
  block.lightList = {0, hasMap ? 1 : 0, hasMap ? 1 : 0, 0};
  auto index = [&block](int k) -> std::int32_t& { return block.lightIndices[k / 4][k % 4]; };
  for (int k = 0; k < kMaxLightsPerObject; ++k) index(k) = -1;
  if (!frame.objectLists.empty()) {
    const ObjectLightList& list = frame.objectLists[object];
    block.lightList.x = list.count;
    block.lightList.w = 1;
    for (int k = 0; k < int(list.indices.size()); ++k) index(k) = list.indices[k];
  }
  // Every vertex in front of the camera: the bounding sphere wholly past the
  // camera plane (an orthographic camera's w is 1 everywhere).
  const bool inFront = frame.view.camera.projection == Projection::Orthographic ||
                       frame.view.viewDepth(geometry.bounds.centre) > geometry.bounds.radius;
  block.raster = {inFront ? 1 : 0, 0, 0, 0};
  if (obj.mesh.type == MeshType::Plane) {
    block.lightmapTransform = {float(1.0 / obj.mesh.planeSizeX), float(1.0 / obj.mesh.planeSizeZ), 0.5f, 0.5f};
  }
  return block;
}

std::vector<GpuVertex> packVertices(const Mesh& mesh) {
  std::vector<GpuVertex> out(mesh.positions.size());
  for (std::size_t i = 0; i < out.size(); ++i) {
    const Vec3& p = mesh.positions[i];
    const Vec3& n = mesh.normals[i];
    out[i] = {{float(p.x), float(p.y), float(p.z)}, {float(n.x), float(n.y), float(n.z)}};
  }
  return out;
}

std::vector<std::uint32_t> packIndices(const Mesh& mesh) {
  std::vector<std::uint32_t> out;
  out.reserve(mesh.triangles.size() * 3);
  for (const auto& t : mesh.triangles) out.insert(out.end(), {t.x, t.y, t.z});
  return out;
}

}  // namespace lighting
