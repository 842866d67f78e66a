#include "suite/bench/bench_scenes.h"

#include "lighting/scene_loader.h"

#include <cmath>
#include <optional>
#include <stdexcept>

namespace bench {

using namespace lighting;

namespace {

// Each deferred mode and the light buffer it draws into: read both ways.
struct DeferredMode {
  FrameMode mode;
  DeferredBuffer buffer;
};
constexpr DeferredMode kDeferredModes[] = {{FrameMode::DeferredHdr32, DeferredBuffer::Hdr32},
                                           {FrameMode::DeferredHdr16, DeferredBuffer::Hdr16},
                                           {FrameMode::DeferredLdr8, DeferredBuffer::Ldr8}};

}  // namespace

std::optional<lighting::DeferredBuffer> deferredBufferOf(FrameMode mode) {
  for (const DeferredMode& d : kDeferredModes)
    if (d.mode == mode) return d.buffer;
  return std::nullopt;
}

std::string modeName(FrameMode mode) {
  if (const auto buffer = deferredBufferOf(mode)) return std::string("deferred-").append(deferredBufferName(*buffer));
  switch (mode) {
    case FrameMode::AllLights: return "all-lights";
    case FrameMode::PerObject: return "per-object";
    case FrameMode::Legacy4x4: return "legacy-4+4";
    default: return "?";
  }
}

FrameMode frameModeOf(const Pipeline& pipeline) {
  if (pipeline.path == RenderPath::Deferred)
    for (const DeferredMode& d : kDeferredModes)
      if (d.buffer == pipeline.deferredBuffer) return d.mode;
  if (pipeline.profile == Profile::Legacy) return FrameMode::Legacy4x4;
  return pipeline.lightsPerObject ? FrameMode::PerObject : FrameMode::AllLights;
}

namespace {

std::string gridName(const char* prefix, int i, int k) {
  std::string name(prefix);  // appended, not `prefix + ...`: GCC 12 warns falsely (-Wrestrict) on that
  name += std::to_string(i);
  name += '_';
  name += std::to_string(k);
  return name;
}

}  // namespace

void lightGridFor(int count, int& columns, int& rows) {
  if (count < 1 || (count & (count - 1)) != 0) throw std::invalid_argument("light count must be a power of two");
  int log2 = 0;
  while ((1 << log2) < count) ++log2;
  columns = 1 << ((log2 + 1) / 2);
  rows = count / columns;
}

namespace {

// The view both synthetic scenes share: straight down on y = 0 through an
// orthographic camera kFieldZ units high, so the field fills the image.
constexpr double kFieldZ = 7.2;  // the view's height in world units

Scene topDownScene(int width, int height, const std::string& name) {
  Scene s;
  s.name = name;
  s.sourcePath = "render_bench synthetic " + name;
  s.image = {width, height};
  s.camera = Camera{{0, 10, 0}, {0, 0, 0}, {0, 0, -1}, Projection::Orthographic, 60, kFieldZ, 0.1, 100};
  return s;
}

}  // namespace

namespace {
void setSpecular(Object& object) {
  object.brdf = Brdf::Srp;
  object.metallic = kFieldMetallic;
  object.smoothness = kFieldSmoothness;
}
}  // namespace

// Seen from straight above (orthographic, exactly the field), so every pixel
// is covered. On the 8x8 field of 1280x720 each tile is 1.6 x 0.9 with one
// light of range 0.85 over its centre: a light touches the bounds of its own
// tile, of the tiles next to it (not the diagonal ones) and of the boxes at
// its tile's corners, so each tile gets 3-5 lights and each box 4: per-object
// lists (at most 8) matter against all 64 lights per pixel.
Scene fieldScene(const FieldSpec& spec, const std::string& name) {
  const double fieldX = kFieldZ * spec.width / spec.height;
  Scene s = topDownScene(spec.width, spec.height, name);
  s.pipeline.lightsPerObject = spec.mode == FrameMode::PerObject;
  if (spec.mode == FrameMode::Legacy4x4) {
    s.pipeline.profile = Profile::Legacy;
    s.pipeline.lightsPerObject = true;  // always on in the legacy profile
  }
  if (const auto buffer = deferredBufferOf(spec.mode)) {
    s.pipeline.path = RenderPath::Deferred;
    s.pipeline.deferredBuffer = *buffer;
  }
  const double x0 = -fieldX / 2, z0 = -kFieldZ / 2;
  const double tileX = fieldX / spec.tileColumns, tileZ = kFieldZ / spec.tileRows;
  for (int i = 0; i < spec.tileColumns; ++i) {
    for (int k = 0; k < spec.tileRows; ++k) {
      Object tile;
      tile.name = gridName("tile", i, k);
      tile.mesh.type = MeshType::Plane;
      tile.mesh.planeSizeX = tileX;
      tile.mesh.planeSizeZ = tileZ;
      tile.transform.translate = {x0 + (i + 0.5) * tileX, 0, z0 + (k + 0.5) * tileZ};
      tile.albedo = {0.8, 0.8, 0.8};
      s.objects.push_back(tile);
      if (spec.specularBrdf) setSpecular(s.objects.back());
    }
  }
  if (spec.boxes) {
    for (int i = 1; i < spec.tileColumns; i += 2) {
      for (int k = 1; k < spec.tileRows; k += 2) {
        Object box;
        box.name = gridName("box", i, k);
        box.mesh.type = MeshType::Box;
        box.mesh.boxSize = {0.5, 0.5, 0.5};
        box.transform.translate = {x0 + i * tileX, 0.25, z0 + k * tileZ};
        box.albedo = {0.9, 0.6, 0.3};
        s.objects.push_back(box);
        if (spec.specularBrdf) setSpecular(s.objects.back());
      }
    }
  }
  const double cellX = fieldX / spec.lightColumns, cellZ = kFieldZ / spec.lightRows;
  const double range = 0.85 * std::sqrt(cellX * cellZ / (1.6 * 0.9));
  for (int i = 0; i < spec.lightColumns; ++i) {
    for (int k = 0; k < spec.lightRows; ++k) {
      Light l;
      l.name = gridName("p", i, k);
      l.type = LightType::Point;
      l.position = {x0 + (i + 0.5) * cellX, 0.4, z0 + (k + 0.5) * cellZ};
      l.range = range;
      l.color = {0.5 + 0.5 * (i % 2), 0.5 + 0.5 * (k % 2), 1.0};
      s.lights.push_back(l);
    }
  }
  return s;
}

// The plane fills the view exactly (as the tiles of fieldScene do), so its
// lightmap spans the image: at 16 texels a texel is 0.8 x 0.45 units, wider
// than the pool under the lowest light. The shadowed light stands 1.2 above
// the plane, 1 unit beside a 0.6 box: the shadow is about 1 unit long, with
// sharp edges a bilinear map can only blur.
Scene lightmapScene(const LightmapSpec& spec, const std::string& name) {
  const double fieldX = kFieldZ * spec.width / spec.height;
  Scene s = topDownScene(spec.width, spec.height, name);

  Object plane;
  plane.name = "floor";
  plane.mesh.type = MeshType::Plane;
  plane.mesh.planeSizeX = fieldX;
  plane.mesh.planeSizeZ = kFieldZ;
  plane.albedo = {0.8, 0.8, 0.8};
  plane.isStatic = true;
  plane.lightmapResolution = spec.baked ? spec.resolution : 0;  // real time: nothing to bake
  s.objects.push_back(plane);

  Object box;
  box.name = "occluder";
  box.mesh.type = MeshType::Box;
  box.mesh.boxSize = {0.6, 0.6, 0.6};
  box.transform.translate = {1.5 * fieldX / 12.8, 0.3, 0.5};
  box.albedo = {0, 0, 0};
  s.objects.push_back(box);

  struct PointSpec {
    double x, z, height, range, intensity;
    Vec3 color;
    bool shadows;
  };
  // x, z as fractions of the half field; the shadowed light is the last one.
  const PointSpec points[] = {
      {-0.6, -0.5, 0.4, 2.5, 1.0, {1.0, 0.6, 0.3}, false},
      {-0.2, 0.5, 0.6, 3.0, 1.5, {0.4, 0.8, 1.0}, false},
      {0.6, -0.6, 0.5, 2.5, 1.0, {0.6, 1.0, 0.5}, false},
      {-0.75, 0.55, 0.8, 3.5, 2.0, {1.0, 1.0, 1.0}, false},
      {0.05, 0.14, 1.2, 4.0, 3.0, {1.0, 0.9, 0.8}, true},
  };
  int k = 0;
  for (const PointSpec& p : points) {
    Light l;
    l.name = "p";  // appended, not `"p" + ...`: GCC 12 warns falsely (-Wrestrict) on that
    l.name += std::to_string(k++);
    l.type = LightType::Point;
    l.position = {p.x * fieldX / 2, p.height, p.z * kFieldZ / 2};
    l.range = p.range;
    l.intensity = p.intensity;
    l.color = p.color;
    l.mode = spec.baked ? LightMode::Baked : LightMode::Realtime;
    l.shadows = p.shadows && spec.shadows;
    l.bakeFalloff = BakeFalloff::InverseSquared;
    s.lights.push_back(l);
  }
  return s;
}

}  // namespace bench
