#include "suite/bench/bench_scenes.h"

#include "lighting/scene_words.h"
#include "scene_input/scene_loader.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
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
    case FrameMode::Clustered: return lighting::kClusteredModeName;
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

constexpr double kPi = 3.14159265358979323846;

// The procedural cookies of the cookie field (FieldSpec::cookies): smooth
// patterns with detail at every scale of the texture, so that filtering and
// the coordinates matter, each light's its own (`seed`), none from a file.
std::shared_ptr<CookieImage> cookieImage(int size, const std::function<double(double u, double v)>& value) {
  auto image = std::make_shared<CookieImage>();
  image->width = image->height = size;
  image->texels.resize(std::size_t(size) * std::size_t(size));
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i)
      image->texels[std::size_t(j) * std::size_t(size) + std::size_t(i)] =
          float(std::clamp(value((i + 0.5) / size, (j + 0.5) / size), 0.0, 1.0));
  return image;
}

// Directional, tiled: whole periods in u and v, so the tile repeats seamlessly.
Cookie tiledCookie(int size) {
  Cookie c;
  c.files = {"procedural:tiled"};
  c.images = {cookieImage(size, [](double u, double v) {
    return 0.55 + 0.25 * std::cos(2 * kPi * u) * std::cos(4 * kPi * v) + 0.2 * std::sin(2 * kPi * (3 * u + v));
  })};
  c.sizeX = c.sizeY = kFieldCookieTile;
  return c;
}

// Spot, projected: spokes that fade to 0 at the inscribed circle, so the
// clamped edge (and everything outside the cone's square) is dark.
Cookie spotCookie(int size, int seed) {
  Cookie c;
  c.files = {"procedural:spot"};
  c.images = {cookieImage(size, [seed](double u, double v) {
    const double x = 2 * u - 1, y = 2 * v - 1, r = std::sqrt(x * x + y * y);
    const double fade = std::clamp((1 - r) / 0.15, 0.0, 1.0);
    return fade * (0.35 + 0.65 * (0.5 + 0.5 * std::cos((5 + seed) * std::atan2(y, x) + 9 * r)));
  })};
  return c;
}

// Point, cube: one function of the direction, so the faces meet without seams.
// Faces +X, -X, +Y, -Y, +Z, -Z: the direction of face coordinates (s, t) in
// [-1, 1] by the cube-map table Vulkan and OpenGL share (lighting/cookie.h).
Vec3 cubeDirection(int face, double s, double t) {
  switch (face) {
    case 0: return {1, -t, -s};
    case 1: return {-1, -t, s};
    case 2: return {s, 1, t};
    case 3: return {s, -1, -t};
    case 4: return {s, -t, 1};
    default: return {-s, -t, -1};
  }
}

Cookie cubeCookie(int size, int seed) {
  Cookie c;
  for (int face = 0; face < 6; ++face) {
    c.files.push_back("procedural:cube");
    c.images.push_back(cookieImage(size, [face, seed](double u, double v) {
      const Vec3 d = glm::normalize(cubeDirection(face, 2 * u - 1, 2 * v - 1));
      return 0.3 + 0.7 * (0.5 + 0.5 * std::cos((8 + 2 * seed) * std::atan2(d.z, d.x))) *
                       (0.5 + 0.5 * std::cos(7 * d.y + seed));
    }));
  }
  return c;
}

bool inCells(const FieldCell (&cells)[2], int i, int k) {
  for (const FieldCell& c : cells)
    if (c.column == i && c.row == k) return true;
  return false;
}

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
  const double range = 0.85 * spec.rangeScale * std::sqrt(cellX * cellZ / (1.6 * 0.9));
  const bool shadowLights = spec.shadowLights || spec.shadows;
  const bool cookieLights = spec.cookieLights || spec.cookies || shadowLights;
  // SPEC 3.9's map of one of the shadow field's lights (FieldSpec::shadows).
  const auto castShadows = [&](Light& light) {
    if (!spec.shadows) return;
    light.shadows = true;
    ShadowMapSpec map;
    map.resolution = spec.shadowResolution;
    map.filter = light.type == LightType::Point && spec.shadowFilter == ShadowFilter::Tent3x3 ? ShadowFilter::Bilinear
                                                                                              : spec.shadowFilter;
    map.depthBias = kFieldShadowDepthBias;
    map.normalBias = kFieldShadowNormalBias;
    map.nearPlane = kFieldShadowNear;
    map.extent = kFieldShadowExtent;
    light.shadowMap = map;
  };
  int seed = 0;  // each cookie its own pattern
  for (int i = 0; i < spec.lightColumns; ++i) {
    for (int k = 0; k < spec.lightRows; ++k) {
      Light l;
      l.name = gridName("p", i, k);
      l.type = LightType::Point;
      l.position = {x0 + (i + 0.5) * cellX, 0.4, z0 + (k + 0.5) * cellZ};
      l.range = range;
      l.color = {0.5 + 0.5 * (i % 2), 0.5 + 0.5 * (k % 2), 1.0};
      if (cookieLights && inCells(kFieldCookieSpots, i, k)) {
        l.type = LightType::Spot;
        l.direction = {0, -1, 0};
        l.spotAngleDeg = kFieldSpotAngleDeg;
        l.innerSpotAngleDeg = kFieldSpotInnerAngleDeg;
        if (spec.cookies) l.cookie = spotCookie(spec.cookieSize, seed++);
        if (shadowLights) castShadows(l);
      } else if (spec.cookies && inCells(kFieldCookieCubes, i, k)) {
        l.cookie = cubeCookie(spec.cookieSize, seed++);
      } else if (shadowLights && i == kFieldShadowCube.column && k == kFieldShadowCube.row) {
        castShadows(l);
      }
      s.lights.push_back(l);
    }
  }
  if (cookieLights) {
    Light sun;
    sun.name = "sun";
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(Vec3(kFieldCookieDirection[0], kFieldCookieDirection[1], kFieldCookieDirection[2]));
    sun.color = {1.0, 0.95, 0.85};
    sun.intensity = 0.5;
    if (spec.cookies) sun.cookie = tiledCookie(spec.cookieSize);
    if (shadowLights) castShadows(sun);
    s.lights.push_back(sun);
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
