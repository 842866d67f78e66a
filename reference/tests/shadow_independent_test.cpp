// The reference's real-time shadow maps (reference/shadow_maps.h) against an
// independent evaluation of SPEC 3.9, written from the SPEC text alone.
//
// Why this file exists: the reference is what every backend is judged by, so
// its shadow maps must not share a mistake with the code that projects them
// (lighting/shadow_projection.h, lighting/light_space.h) or with the BVH that
// traces them. Everything under `namespace model` below is therefore computed
// from SPEC 3.9 and SPEC 2 by hand: its own light basis, its own orthographic,
// perspective and cube projections, its own ray casts against an analytic
// plane and an analytic axis-aligned box (no triangles, no BVH), its own map
// and its own hard / bilinear / tent3x3 lookups. Only glm's vector type and
// its dot/cross/normalize are shared, because the API under test speaks glm.
// The project's loader, prepareScene, buildWorldTriangles and Bvh are used
// only to BUILD the object under test (ReferenceShadowMap).
//
// What is compared:
//  * every texel whose reference interval is narrow (hi - lo < kNarrow, i.e.
//    the texel is not at a caster's silhouette or within the depth error of a
//    second surface) must hold our depth to 1e-9; every texel's interval must
//    contain our depth; at least 90% of the texels must be narrow, so the
//    comparison covers the map and not just its empty corners;
//  * on a grid of receivers on the plane, wherever the reference's lookup is
//    unambiguous (hi - lo < kNarrow with no position error and SPEC's weight
//    precision 2^-4), our s must equal ReferenceShadowMap::value to 1e-9, and
//    everywhere our s must lie in [lo, hi]; a majority must be unambiguous and
//    both lit and shadowed receivers must occur, so the test cannot pass
//    vacuously;
//  * shadowFade and shadowAttenuation against SPEC 3.9's formulas;
//  * the scene-format errors of SPEC 2's `shadow_map` bullet.
//
// Why "narrow" is kNarrow = 1e-3 and not "hi == lo": the reference keeps, on
// every texel a surface covers, the band of depths a correct float32 shadow
// pass may store (8 ulps of depth, the camera-relative position error times
// the depth slope, the rasteriser's snapping on steep faces such as the box's
// sides). Measured on these scenes that band is 1e-6 .. 1e-3 wide on every
// covered texel, so hi - lo < 1e-6 would only ever select empty texels
// (depth 1). In the same way tent3x3 lookups whose 16 texels all compare
// alike carry spans of 5e-4 .. 1e-3 (bilinear ones 1e-16). A real ambiguity
// (a silhouette admitting the surface behind it, a compare that may flip, a
// texel or face in doubt) moves a depth by a surface-to-surface gap or s by
// a filter weight, both well above 1e-3 here except for the smallest tent
// weights. The counts of exactly zero spans are printed beside the others.
#include "lighting/frame.h"
#include "lighting/shadow_projection.h"
#include "reference/bvh.h"
#include "reference/shadow_maps.h"
#include "reference/world_triangles.h"
#include "scene_input/scene_loader.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace {

using glm::dvec3;

// See the file comment: the widest interval still counted as unambiguous.
constexpr double kNarrow = 1e-3;

// ---------------------------------------------------------------------------
// The independent model of SPEC 3.9 (nothing here calls project code).
// ---------------------------------------------------------------------------
namespace model {

// The scene of this file: "a plane with one box". SPEC 2: an unrotated plane
// of scale 1 is the square |x - tx| <= sx/2, |z - tz| <= sz/2 at y = ty; an
// unrotated box of scale 1 is the axis-aligned box of `size` centred on its
// translate. SPEC 3.9: every triangle casts with both faces, so the plane
// casts from below as well as from above, and a ray from inside the box hits
// its far side.
struct Geometry {
  dvec3 planeCentre{0, 0, 0};
  double planeSizeX = 10, planeSizeZ = 10;
  dvec3 boxCentre{0.3, 0.8, -0.2};
  dvec3 boxSize{1, 1, 1};
};

// The nearest hit t in [tMin, tMax] of the ray o + t d (d need not be unit
// length), or nothing.
std::optional<double> nearestHit(const Geometry& g, const dvec3& o, const dvec3& d, double tMin, double tMax) {
  std::optional<double> best;
  const auto consider = [&](double t) {
    if (t >= tMin && t <= tMax && (!best || t < *best)) best = t;
  };
  // The plane: both faces cast.
  if (d.y != 0) {
    const double t = (g.planeCentre.y - o.y) / d.y;
    const dvec3 q = o + t * d;
    if (std::abs(q.x - g.planeCentre.x) <= g.planeSizeX / 2 && std::abs(q.z - g.planeCentre.z) <= g.planeSizeZ / 2)
      consider(t);
  }
  // The box, by slabs: its surface is where the ray enters and leaves it.
  const dvec3 lo = g.boxCentre - g.boxSize / 2.0, hi = g.boxCentre + g.boxSize / 2.0;
  double tEnter = -INFINITY, tExit = INFINITY;
  bool misses = false;
  for (int a = 0; a < 3; ++a) {
    if (d[a] == 0) {
      if (o[a] < lo[a] || o[a] > hi[a]) misses = true;
      continue;
    }
    double t0 = (lo[a] - o[a]) / d[a], t1 = (hi[a] - o[a]) / d[a];
    if (t0 > t1) std::swap(t0, t1);
    tEnter = std::max(tEnter, t0);
    tExit = std::min(tExit, t1);
  }
  if (!misses && tEnter <= tExit) {
    consider(tEnter);
    consider(tExit);
  }
  return best;
}

enum class Type { Directional, Spot, Point };
enum class Filter { Hard, Bilinear, Tent3x3 };

struct Light {
  Type type = Type::Directional;
  dvec3 position{0, 0, 0};   // spot, point
  dvec3 direction{0, -1, 0}; // directional, spot: the way the light travels (normalised here)
  double range = 10;         // spot, point
  double spotAngleDeg = 90;  // spot
  int resolution = 64;
  Filter filter = Filter::Bilinear;
  double depthBias = 0.05, normalBias = 0;
  double nearPlane = 0.05;   // spot, point
  dvec3 center{0, 0, 0};     // directional
  double extent = 10;        // directional
};

// SPEC 3.9's light basis: f = direction, r = normalize(cross(f, up)),
// u = cross(r, f), up = +Y, or +Z when |f.y| > 0.99.
struct Basis {
  dvec3 r, u, f;
};
Basis basisOf(const dvec3& direction) {
  Basis b;
  b.f = glm::normalize(direction);
  const dvec3 up = std::abs(b.f.y) > 0.99 ? dvec3(0, 0, 1) : dvec3(0, 1, 0);
  b.r = glm::normalize(glm::cross(b.f, up));
  b.u = glm::cross(b.r, b.f);
  return b;
}

// SPEC 3.9 point light: the standard cube-map faces +X, -X, +Y, -Y, +Z, -Z
// with the face table Vulkan and OpenGL share. For a direction d on face k:
// ma = dot(d, axis), sc = dot(d, s), tc = dot(d, t), and the face coordinates
// are u = (sc/|ma| + 1)/2, v = (tc/|ma| + 1)/2:
//   +X: sc = -z, tc = -y    -X: sc = +z, tc = -y
//   +Y: sc = +x, tc = +z    -Y: sc = +x, tc = -z
//   +Z: sc = +x, tc = -y    -Z: sc = -x, tc = -y
struct CubeFace {
  dvec3 axis, s, t;
};
const CubeFace kFaces[6] = {
    {{1, 0, 0}, {0, 0, -1}, {0, -1, 0}},  {{-1, 0, 0}, {0, 0, 1}, {0, -1, 0}},
    {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}},    {{0, -1, 0}, {1, 0, 0}, {0, 0, -1}},
    {{0, 0, 1}, {1, 0, 0}, {0, -1, 0}},   {{0, 0, -1}, {-1, 0, 0}, {0, -1, 0}},
};

// Perspective depth as Vulkan stores z/w with near -> 0 and far -> 1.
double perspectiveDepth(double z, double nearPlane, double farPlane) {
  return farPlane * (z - nearPlane) / ((farPlane - nearPlane) * z);
}

int viewCount(const Light& l) { return l.type == Type::Point ? 6 : 1; }

// Where a point lands: map coordinates, depth, and whether it is outside the
// map (SPEC 3.9: mu, mv or depth outside [0, 1], or behind a spot's apex).
struct Projected {
  int view = 0;
  double mu = 0, mv = 0, depth = 0;
  bool outside = false;
};

Projected project(const Light& l, const dvec3& q) {
  Projected p;
  if (l.type == Type::Directional) {
    const Basis b = basisOf(l.direction);
    const dvec3 d = q - l.center;
    p.mu = (glm::dot(d, b.r) / l.extent + 1) / 2;
    p.mv = (glm::dot(d, b.u) / l.extent + 1) / 2;
    p.depth = (glm::dot(d, b.f) / l.extent + 1) / 2;
  } else if (l.type == Type::Spot) {
    const Basis b = basisOf(l.direction);
    const dvec3 d = q - l.position;
    const double z = glm::dot(d, b.f);
    if (z <= 0) {
      p.outside = true;
      return p;
    }
    const double tanHalf = std::tan(l.spotAngleDeg * M_PI / 360.0);
    p.mu = (glm::dot(d, b.r) / (z * tanHalf) + 1) / 2;
    p.mv = (glm::dot(d, b.u) / (z * tanHalf) + 1) / 2;
    p.depth = perspectiveDepth(z, l.nearPlane, l.range);
  } else {
    const dvec3 d = q - l.position;
    const dvec3 a = glm::abs(d);
    // The major axis picks the face (ties are left to chance; the scenes
    // below do not sample them on purpose).
    int axis = 0;
    if (a.y > a.x && a.y >= a.z) axis = 1;
    else if (a.z > a.x && a.z > a.y) axis = 2;
    p.view = 2 * axis + (d[axis] < 0 ? 1 : 0);
    const CubeFace& face = kFaces[p.view];
    const double ma = std::abs(glm::dot(d, face.axis));
    p.mu = (glm::dot(d, face.s) / ma + 1) / 2;
    p.mv = (glm::dot(d, face.t) / ma + 1) / 2;
    p.depth = perspectiveDepth(ma, l.nearPlane, l.range);
  }
  p.outside = p.mu < 0 || p.mu > 1 || p.mv < 0 || p.mv > 1 || p.depth < 0 || p.depth > 1;
  return p;
}

// The map, built by a ray through every texel centre ((i + 0.5)/N, (j + 0.5)/N):
// the normalised depth of the nearest surface inside the view's depth range
// [0, 1], or 1 where nothing is hit.
struct Map {
  int n = 0;
  std::vector<double> depth;  // [view][j][i]
  double at(int view, int i, int j) const { return depth[(std::size_t(view) * n + j) * n + i]; }
};

double texelDepth(const Geometry& g, const Light& l, int view, int i, int j) {
  const int n = l.resolution;
  const double mu = (i + 0.5) / n, mv = (j + 0.5) / n;
  const double x = 2 * mu - 1, y = 2 * mv - 1;  // [0, 1] -> [-1, 1]
  if (l.type == Type::Directional) {
    // The box of half-size `extent` around `center`: the ray enters at the
    // near face (depth 0) and travels along f for 2 extent (depth 1).
    const Basis b = basisOf(l.direction);
    const dvec3 o = l.center + l.extent * x * b.r + l.extent * y * b.u - l.extent * b.f;
    const auto t = nearestHit(g, o, b.f, 0, 2 * l.extent);
    return t ? *t / (2 * l.extent) : 1.0;
  }
  // Perspective: a direction whose component along the view axis is 1, so the
  // ray parameter is the view depth z, kept in [near, far = range].
  dvec3 d;
  if (l.type == Type::Spot) {
    const Basis b = basisOf(l.direction);
    const double tanHalf = std::tan(l.spotAngleDeg * M_PI / 360.0);
    d = b.f + x * tanHalf * b.r + y * tanHalf * b.u;
  } else {
    const CubeFace& face = kFaces[view];
    d = face.axis + x * face.s + y * face.t;
  }
  const auto z = nearestHit(g, l.position, d, l.nearPlane, l.range);
  return z ? perspectiveDepth(*z, l.nearPlane, l.range) : 1.0;
}

Map buildMap(const Geometry& g, const Light& l) {
  Map m;
  m.n = l.resolution;
  m.depth.resize(std::size_t(viewCount(l)) * m.n * m.n);
  for (int v = 0; v < viewCount(l); ++v)
    for (int j = 0; j < m.n; ++j)
      for (int i = 0; i < m.n; ++i) m.depth[(std::size_t(v) * m.n + j) * m.n + i] = texelDepth(g, l, v, i, j);
  return m;
}

// SPEC 3.9: lit by a texel when depth(p') <= texel (LESS_OR_EQUAL).
double compare(double depth, double texel) { return depth <= texel ? 1.0 : 0.0; }

// A compare sampler with linear filtering and clamp to edge at (mu, mv):
// x = mu N - 0.5, i0 = floor(x), a = x - i0, the four texels around it.
double bilinearCompare(const Map& m, int view, double mu, double mv, double depth) {
  const int n = m.n;
  const double x = mu * n - 0.5, y = mv * n - 0.5;
  const double fx = std::floor(x), fy = std::floor(y);
  const double a = x - fx, b = y - fy;
  const int i0 = int(fx), j0 = int(fy);
  const auto tap = [&](int i, int j) {
    return compare(depth, m.at(view, std::clamp(i, 0, n - 1), std::clamp(j, 0, n - 1)));
  };
  return (1 - a) * (1 - b) * tap(i0, j0) + a * (1 - b) * tap(i0 + 1, j0) + (1 - a) * b * tap(i0, j0 + 1) +
         a * b * tap(i0 + 1, j0 + 1);
}

// SPEC 3.9's tent3x3 per axis: c = floor(x + 0.5), o = x - c and the weights
// w0..w3; two fetches of weights (w0 + w1, w2 + w3) at offsets
// (w1/(w0 + w1) - 1.5, w3/(w2 + w3) + 0.5)/N from c/N.
struct TentAxis {
  double weight[2], coord[2];
};
TentAxis tentAxis(double mu, int n) {
  const double x = mu * n;
  const double c = std::floor(x + 0.5);
  const double o = x - c;
  const double w0 = ((o + 0.5) * (o + 0.5) / 2 - o) * 4 / 9;
  const double w1 = ((1.5 - o) - 0.5 - std::min(o, 0.0) * std::min(o, 0.0)) * 4 / 9;
  const double w2 = ((1.5 + o) - 0.5 - std::max(o, 0.0) * std::max(o, 0.0)) * 4 / 9;
  const double w3 = ((o + 0.5) * (o + 0.5) / 2) * 4 / 9;
  TentAxis t;
  t.weight[0] = w0 + w1;
  t.weight[1] = w2 + w3;
  t.coord[0] = c / n + (w1 / (w0 + w1) - 1.5) / n;
  t.coord[1] = c / n + (w3 / (w2 + w3) + 0.5) / n;
  return t;
}

// SPEC 3.9's s at receiver p with unit normal n. `footprintInFace` is set to
// whether the 2x2 bilinear footprint at (mu, mv) lies inside one view without
// clamping (always meaningful; the caller uses it for cube maps).
double lookup(const Map& m, const Light& l, const dvec3& p, const dvec3& n, bool* footprintInFace = nullptr) {
  const dvec3 L = l.type == Type::Directional ? -glm::normalize(l.direction) : glm::normalize(l.position - p);
  const dvec3 q = p + l.normalBias * n + l.depthBias * L;
  const Projected pr = project(l, q);
  if (footprintInFace) {
    const double x = pr.mu * m.n - 0.5, y = pr.mv * m.n - 0.5;
    const auto inside = [&](double t) { return std::floor(t) >= 0 && std::floor(t) + 1 <= m.n - 1; };
    *footprintInFace = !pr.outside && inside(x) && inside(y);
  }
  if (pr.outside) return 1.0;
  switch (l.filter) {
    case Filter::Hard: {
      const int i = std::min(int(std::floor(pr.mu * m.n)), m.n - 1);
      const int j = std::min(int(std::floor(pr.mv * m.n)), m.n - 1);
      return compare(pr.depth, m.at(pr.view, i, j));
    }
    case Filter::Bilinear:
      return bilinearCompare(m, pr.view, pr.mu, pr.mv, pr.depth);
    case Filter::Tent3x3: {
      const TentAxis tu = tentAxis(pr.mu, m.n), tv = tentAxis(pr.mv, m.n);
      double s = 0;
      for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b)
          s += tu.weight[a] * tv.weight[b] * bilinearCompare(m, pr.view, tu.coord[a], tv.coord[b], pr.depth);
      return s;
    }
  }
  return 1.0;
}

// SPEC 3.9: fade = saturate((z - 0.8 S)/(0.2 S)), 0 when S = 0;
// shadowAtten = saturate(lerp(1, s, strength) + fade).
double saturate(double x) { return std::clamp(x, 0.0, 1.0); }
double fade(double S, double z) { return S == 0 ? 0.0 : saturate((z - 0.8 * S) / (0.2 * S)); }
double attenuation(double s, double strength, double fadeValue) {
  return saturate((1 - strength) * 1.0 + strength * s + fadeValue);
}

}  // namespace model

// ---------------------------------------------------------------------------
// Scene text (SPEC 2) for the model's geometry and light.
// ---------------------------------------------------------------------------
std::string vec(const dvec3& v) {
  std::ostringstream s;
  s.precision(17);
  s << "[" << v.x << ", " << v.y << ", " << v.z << "]";
  return s.str();
}
std::string num(double x) {
  std::ostringstream s;
  s.precision(17);
  s << x;
  return s.str();
}
const char* filterName(model::Filter f) {
  switch (f) {
    case model::Filter::Hard: return "hard";
    case model::Filter::Bilinear: return "bilinear";
    case model::Filter::Tent3x3: return "tent3x3";
  }
  return "?";
}

std::string sceneText(const model::Geometry& g, const model::Light& l, int planeSubdivisions) {
  std::ostringstream s;
  s << R"({"lightcts": 1, "image": {"width": 32, "height": 32},)"
    << R"("camera": {"position": [0, 10, 0], "target": [0, 0, 0], "up": [0, 0, -1],)"
    << R"("projection": "orthographic", "height": 10, "near": 0.1, "far": 100},)"
    << R"("objects": [)"
    << R"({"name": "floor", "mesh": {"type": "plane", "size": [)" << num(g.planeSizeX) << ", " << num(g.planeSizeZ)
    << R"(], "subdivisions": )" << planeSubdivisions << "},"
    << R"("transform": {"translate": )" << vec(g.planeCentre) << R"(, "rotate_deg": [0, 0, 0], "scale": 1},)"
    << R"("material": {"albedo": [1, 1, 1]}},)"
    << R"({"name": "box", "mesh": {"type": "box", "size": )" << vec(g.boxSize) << "},"
    << R"("transform": {"translate": )" << vec(g.boxCentre) << R"(, "rotate_deg": [0, 0, 0], "scale": 1},)"
    << R"("material": {"albedo": [1, 1, 1]}}],)"
    << R"("lights": [{"name": "l0", )";
  switch (l.type) {
    case model::Type::Directional:
      s << R"("type": "directional", "direction": )" << vec(l.direction) << ",";
      break;
    case model::Type::Spot:
      s << R"("type": "spot", "position": )" << vec(l.position) << R"(, "direction": )" << vec(l.direction)
        << R"(, "range": )" << num(l.range) << R"(, "spot_angle_deg": )" << num(l.spotAngleDeg)
        << R"(, "inner_spot_angle_deg": 0,)";
      break;
    case model::Type::Point:
      s << R"("type": "point", "position": )" << vec(l.position) << R"(, "range": )" << num(l.range) << ",";
      break;
  }
  s << R"("color": [1, 1, 1], "intensity": 1, "mode": "realtime", "shadows": true, "shadow_strength": 1,)"
    << R"("shadow_map": {"resolution": )" << l.resolution << R"(, "filter": ")" << filterName(l.filter)
    << R"(", "depth_bias": )" << num(l.depthBias) << R"(, "normal_bias": )" << num(l.normalBias);
  if (l.type == model::Type::Directional)
    s << R"(, "center": )" << vec(l.center) << R"(, "extent": )" << num(l.extent);
  else
    s << R"(, "near": )" << num(l.nearPlane);
  s << "}}]}";
  return s.str();
}

// The object under test, built the way the reference renderer builds it.
struct Built {
  std::shared_ptr<const lighting::PreparedScene> prepared;
  std::unique_ptr<reference::WorldTriangles> world;  // outlives bvh
  std::unique_ptr<reference::Bvh> bvh;
  std::unique_ptr<reference::ReferenceShadowMap> map;
};

Built buildReference(const model::Geometry& g, const model::Light& l, int planeSubdivisions) {
  Built b;
  lighting::Scene scene = scene_input::loadSceneText(sceneText(g, l, planeSubdivisions), "shadow_independent.json");
  b.prepared = lighting::prepareScene(std::move(scene));
  const lighting::Frame frame = lighting::prepareFrame(b.prepared, 0);
  b.world = std::make_unique<reference::WorldTriangles>(reference::buildWorldTriangles(*b.prepared));
  b.bvh = std::make_unique<reference::Bvh>(*b.world);
  b.map = std::make_unique<reference::ReferenceShadowMap>(lighting::shadowProjection(b.prepared->scene, 0), *b.bvh,
                                                          frame.view.camera.position);
  return b;
}

// ---------------------------------------------------------------------------
// The scenes: a 10 x 10 plane at y = 0 and a unit box raised to y in
// [0.3, 1.3], so it casts onto the plane and the maps also see its sides.
// ---------------------------------------------------------------------------
model::Light directionalLight(model::Filter filter) {
  model::Light l;
  l.type = model::Type::Directional;
  l.direction = glm::normalize(dvec3(0.4, -1, 0.3));  // |f.y| = 0.89: up = +Y
  l.center = {0, 0, 0};
  l.extent = 6;
  l.resolution = 64;
  l.filter = filter;
  // Enough bias that the plane does not shadow itself anywhere in tent3x3's
  // 4 x 4 footprint (its depth rises ~0.1 m per texel toward the light).
  l.depthBias = 0.15;
  l.normalBias = 0.05;
  return l;
}

// Nearly straight down: |f.y| > 0.99, so the basis takes up = +Z.
model::Light steepDirectionalLight(model::Filter filter) {
  model::Light l;
  l.type = model::Type::Directional;
  l.direction = glm::normalize(dvec3(0.05, -1, 0.03));
  l.center = {0.5, 0.5, 0};
  l.extent = 5.5;
  l.resolution = 128;
  l.filter = filter;
  l.depthBias = 0.03;
  l.normalBias = 0;
  return l;
}

model::Light spotLight(model::Filter filter) {
  model::Light l;
  l.type = model::Type::Spot;
  l.position = {1.5, 5.0, 1.0};
  l.direction = glm::normalize(dvec3(-1.2, -4.2, -1.2));  // toward the box; |f.y| = 0.93: up = +Y
  l.range = 12;
  // Narrow enough that the cone's edge meets the plane at most ~50 degrees
  // off its normal: at grazing incidence the plane's depth climbs faster
  // across tent3x3's 4 x 4 footprint than any constant bias (SPEC 3.9 has no
  // slope bias), and the lookups would be self-shadowing rather than a test.
  l.spotAngleDeg = 60;
  l.nearPlane = 0.1;
  l.resolution = 64;
  l.filter = filter;
  l.depthBias = 0.1;
  l.normalBias = 0.03;
  return l;
}

// Below the plane, looking up: the plane's back face casts (SPEC 3.9: both
// faces), and |f.y| > 0.99 puts the spot's basis on up = +Z.
model::Light spotFromBelow(model::Filter filter) {
  model::Light l;
  l.type = model::Type::Spot;
  l.position = {0.5, -2.5, 0.3};
  l.direction = glm::normalize(dvec3(0.05, 1, -0.04));
  l.range = 9;
  l.spotAngleDeg = 120;
  l.nearPlane = 0.2;
  l.resolution = 64;
  l.filter = filter;
  l.depthBias = 0.04;
  l.normalBias = 0.01;
  return l;
}

model::Light pointLight(model::Filter filter) {
  model::Light l;
  l.type = model::Type::Point;
  // High enough, and a map fine enough, that the plane's far corners are not
  // so grazing that the constant bias leaves them self-shadowing in the
  // bilinear footprint (as for the spot above).
  l.position = {1.8, 4.0, 1.2};
  l.range = 12;
  l.nearPlane = 0.1;
  l.resolution = 128;
  l.filter = filter;
  l.depthBias = 0.08;
  l.normalBias = 0.03;
  return l;
}

std::string describe(const model::Light& l) {
  const char* type = l.type == model::Type::Directional ? "directional"
                     : l.type == model::Type::Spot      ? "spot"
                                                        : "point";
  return std::string(type) + " light, filter " + filterName(l.filter) + ", resolution " + std::to_string(l.resolution);
}

// ---------------------------------------------------------------------------
// Check 1: the maps.
// ---------------------------------------------------------------------------
void checkMapDepths(const model::Light& light, int planeSubdivisions = 1) {
  SCOPED_TRACE(describe(light));
  const model::Geometry g;
  const Built built = buildReference(g, light, planeSubdivisions);
  const reference::ReferenceShadowMap& ref = *built.map;
  ASSERT_EQ(ref.resolution(), light.resolution);
  ASSERT_EQ(ref.viewCount(), model::viewCount(light));
  const model::Map ours = model::buildMap(g, light);

  long total = 0, narrow = 0, narrowMismatch = 0, outsideInterval = 0, covered = 0, coveredNarrow = 0, exact = 0,
       anyMismatch = 0;
  for (int v = 0; v < ref.viewCount(); ++v) {
    for (int j = 0; j < ref.resolution(); ++j) {
      for (int i = 0; i < ref.resolution(); ++i) {
        const reference::ShadowTexel& t = ref.texel(v, i, j);
        const double mine = ours.at(v, i, j);
        ++total;
        if (mine < 1) ++covered;
        // A reference interval that excludes the true depth is a bug in it.
        if (!(t.lo - 1e-12 <= mine && mine <= t.hi + 1e-12)) {
          if (++outsideInterval <= 10)
            ADD_FAILURE() << "view " << v << " texel (" << i << ", " << j << "): our depth " << mine
                          << " outside the reference's [" << t.lo << ", " << t.hi << "] (depth " << t.depth << ")";
        }
        if (std::abs(t.depth - mine) > 1e-9) ++anyMismatch;
        if (t.hi == t.lo) ++exact;
        if (t.hi - t.lo < kNarrow) {
          ++narrow;
          if (mine < 1) ++coveredNarrow;
          if (std::abs(t.depth - mine) > 1e-9 && ++narrowMismatch <= 10)
            ADD_FAILURE() << "view " << v << " texel (" << i << ", " << j << "): reference depth " << t.depth
                          << ", ours " << mine << " (interval [" << t.lo << ", " << t.hi << "])";
        }
      }
    }
  }
  EXPECT_EQ(outsideInterval, 0);
  EXPECT_EQ(narrowMismatch, 0);
  EXPECT_GE(double(narrow), 0.9 * double(total)) << narrow << " of " << total << " texels unambiguous";
  // Not vacuous: the plane and the box cover a good part of the map, and most
  // of the covered texels are compared exactly.
  EXPECT_GE(coveredNarrow, covered / 2) << coveredNarrow << " of " << covered << " covered texels unambiguous";
  EXPECT_GT(covered, total / 10);
  std::printf("[ shadow map ] %s: %ld texels, %ld unambiguous (%.2f%%; %ld with hi == lo), %ld covered "
              "(%ld unambiguous); our depth differs from the reference's by > 1e-9 at %ld texels\n",
              describe(light).c_str(), total, narrow, 100.0 * narrow / total, exact, covered, coveredNarrow,
              anyMismatch);
}

// ---------------------------------------------------------------------------
// Check 2: the lookups on a grid of receivers on the plane (N = +Y on its top
// face, N = -Y on its bottom face for a light below it).
// ---------------------------------------------------------------------------
void checkLookups(const model::Light& light, const dvec3& normal = {0, 1, 0}, int grid = 64) {
  SCOPED_TRACE(describe(light));
  const model::Geometry g;
  const Built built = buildReference(g, light, 1);
  const reference::ReferenceShadowMap& ref = *built.map;
  const model::Map ours = model::buildMap(g, light);
  const double weightPrecision = std::ldexp(1.0, -4);  // SPEC 3.9: 2^-4

  long compared = 0, unique = 0, lit = 0, shadowed = 0, mismatch = 0, outside = 0, skipped = 0, valueDiffers = 0,
       exactlyUnique = 0;
  for (int b = 0; b < grid; ++b) {
    for (int a = 0; a < grid; ++a) {
      const dvec3 p(g.planeCentre.x - g.planeSizeX / 2 + g.planeSizeX * (a + 0.5) / grid, g.planeCentre.y,
                    g.planeCentre.z - g.planeSizeZ / 2 + g.planeSizeZ * (b + 0.5) / grid);
      bool inFace = true;
      const double mine = model::lookup(ours, light, p, normal, &inFace);
      // A cube map filters across faces seamlessly (SPEC 3.9); this model
      // does not build the seamless footprint, so for a point light's
      // bilinear filter it only compares receivers whose 2x2 footprint stays
      // inside one face (the hard filter reads one texel: compared anywhere).
      if (light.type == model::Type::Point && light.filter != model::Filter::Hard && !inFace) {
        ++skipped;
        continue;
      }
      ++compared;
      const reference::ShadowLookup r = ref.lookup(p, normal, reference::LookupError{0}, weightPrecision);
      const double value = ref.value(p, normal);
      if (std::abs(value - mine) > 1e-9) ++valueDiffers;
      if (!(r.lo - 1e-9 <= mine && mine <= r.hi + 1e-9) && ++outside <= 10)
        ADD_FAILURE() << "receiver (" << p.x << ", " << p.y << ", " << p.z << "): our s " << mine
                      << " outside the reference's [" << r.lo << ", " << r.hi << "] (value " << value << ")";
      if (r.hi == r.lo) ++exactlyUnique;
      if (r.hi - r.lo < kNarrow) {
        ++unique;
        if (mine > 1 - 1e-9) ++lit;
        if (mine < 1e-9) ++shadowed;
        if (std::abs(value - mine) > 1e-9 && ++mismatch <= 10)
          ADD_FAILURE() << "receiver (" << p.x << ", " << p.y << ", " << p.z << "): reference value " << value
                        << ", lookup s " << r.s << ", ours " << mine;
      }
    }
  }
  EXPECT_EQ(outside, 0);
  EXPECT_EQ(mismatch, 0);
  EXPECT_GT(2 * unique, compared) << unique << " of " << compared << " lookups unambiguous";
  EXPECT_GT(lit, 0);
  EXPECT_GT(shadowed, 0);
  // Beyond the unambiguous points: value() and our s are both SPEC 3.9's s
  // in double, so they may part only where a compare sits within rounding of
  // its boundary; allow that at 1% of the points (none seen so far).
  EXPECT_LE(100 * valueDiffers, compared) << "value() differs from our s at " << valueDiffers << " points";
  std::printf("[ shadow lookup ] %s: %ld compared (%ld skipped at cube face edges), %ld unambiguous (%.2f%%; %ld "
              "with hi == lo), %ld lit, %ld shadowed; value() differs from ours at %ld\n",
              describe(light).c_str(), compared, skipped, unique, 100.0 * unique / std::max(compared, 1L),
              exactlyUnique, lit, shadowed, valueDiffers);
}

// ---- maps -----------------------------------------------------------------

TEST(ShadowIndependent, DirectionalMapDepthsMatchAtUnambiguousTexels) {
  checkMapDepths(directionalLight(model::Filter::Bilinear));
}

TEST(ShadowIndependent, SteepDirectionalMapDepthsMatchAtUnambiguousTexels) {
  // up = +Z branch of the basis; a subdivided plane, whose inner triangle
  // edges are no silhouettes and must not widen the intervals much.
  checkMapDepths(steepDirectionalLight(model::Filter::Bilinear), 3);
}

TEST(ShadowIndependent, SpotMapDepthsMatchAtUnambiguousTexels) {
  checkMapDepths(spotLight(model::Filter::Bilinear));
}

TEST(ShadowIndependent, SpotFromBelowMapDepthsMatchAtUnambiguousTexels) {
  checkMapDepths(spotFromBelow(model::Filter::Bilinear));
}

TEST(ShadowIndependent, PointCubeMapDepthsMatchAtUnambiguousTexels) {
  checkMapDepths(pointLight(model::Filter::Bilinear));
}

// ---- lookups --------------------------------------------------------------

TEST(ShadowIndependent, DirectionalHardLookupsMatch) { checkLookups(directionalLight(model::Filter::Hard)); }
TEST(ShadowIndependent, DirectionalBilinearLookupsMatch) { checkLookups(directionalLight(model::Filter::Bilinear)); }
TEST(ShadowIndependent, DirectionalTent3x3LookupsMatch) { checkLookups(directionalLight(model::Filter::Tent3x3)); }

TEST(ShadowIndependent, SteepDirectionalLookupsMatch) {
  checkLookups(steepDirectionalLight(model::Filter::Hard));
  checkLookups(steepDirectionalLight(model::Filter::Bilinear));
  checkLookups(steepDirectionalLight(model::Filter::Tent3x3));
}

TEST(ShadowIndependent, SpotHardLookupsMatch) { checkLookups(spotLight(model::Filter::Hard)); }
TEST(ShadowIndependent, SpotBilinearLookupsMatch) { checkLookups(spotLight(model::Filter::Bilinear)); }
TEST(ShadowIndependent, SpotTent3x3LookupsMatch) { checkLookups(spotLight(model::Filter::Tent3x3)); }

TEST(ShadowIndependent, PointHardLookupsMatch) { checkLookups(pointLight(model::Filter::Hard)); }
TEST(ShadowIndependent, PointBilinearLookupsMatchInsideFaces) { checkLookups(pointLight(model::Filter::Bilinear)); }

// SPEC 3.9: outside the map (mu or mv outside [0, 1], depth outside [0, 1],
// behind a spot's apex) s = 1. Receivers chosen well clear of every boundary.
TEST(ShadowIndependent, OutsideTheMapIsLit) {
  const model::Geometry g;
  struct Case {
    model::Light light;
    dvec3 p;
    const char* what;
  };
  const model::Light d = directionalLight(model::Filter::Bilinear);
  const model::Basis db = model::basisOf(d.direction);
  const model::Light sp = spotLight(model::Filter::Hard);
  const dvec3 sf = glm::normalize(sp.direction);
  const model::Light pt = pointLight(model::Filter::Hard);
  const std::vector<Case> cases = {
      {d, d.center + 1.3 * d.extent * db.r, "directional: mu > 1"},
      {d, d.center - 1.3 * d.extent * db.u, "directional: mv < 0"},
      {d, d.center - 1.3 * d.extent * db.f, "directional: depth < 0 (before the box)"},
      {sp, sp.position - 2.0 * sf, "spot: behind the apex"},
      {sp, sp.position + 0.5 * sp.nearPlane * sf, "spot: nearer than near"},
      {sp, sp.position + 1.2 * sp.range * sf, "spot: beyond range"},
      {sp, sp.position + 3.0 * sf + 3.0 * model::basisOf(sp.direction).r, "spot: outside the cone (mu > 1)"},
      {pt, pt.position + dvec3(1.2 * pt.range, 0.5, -0.3), "point: beyond range on +X"},
      {pt, pt.position + dvec3(0.2, -0.5 * pt.nearPlane, 0.1) * 0.5, "point: nearer than near on -Y"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    const Built built = buildReference(g, c.light, 1);
    const model::Map ours = model::buildMap(g, c.light);
    const dvec3 N(0, 1, 0);
    EXPECT_EQ(model::lookup(ours, c.light, c.p, N), 1.0);
    EXPECT_EQ(built.map->value(c.p, N), 1.0);
    const reference::ShadowLookup r = built.map->lookup(c.p, N, reference::LookupError{0}, std::ldexp(1.0, -4));
    EXPECT_EQ(r.lo, 1.0);
    EXPECT_EQ(r.hi, 1.0);
  }
}

// ---- fade and attenuation ---------------------------------------------------

TEST(ShadowIndependent, FadeAndAttenuationFollowTheFormula) {
  for (double S : {0.0, 1.0, 10.0, 37.5}) {
    for (double z : {-1.0, 0.0, 0.5, 7.9, 8.0, 8.5, 9.0, 10.0, 12.0, 30.0, 31.0, 36.0, 40.0}) {
      EXPECT_NEAR(lighting::shadowFade(S, z), model::fade(S, z), 1e-15) << "S " << S << " z " << z;
    }
  }
  EXPECT_EQ(lighting::shadowFade(0, 1e9), 0.0);
  EXPECT_NEAR(lighting::shadowFade(10, 9), 0.5, 1e-15);
  for (double s : {0.0, 0.25, 0.5, 1.0}) {
    for (double strength : {0.0, 0.3, 1.0}) {
      for (double f : {0.0, 0.2, 0.6, 1.0}) {
        EXPECT_NEAR(lighting::shadowAttenuation(s, strength, f), model::attenuation(s, strength, f), 1e-15)
            << "s " << s << " strength " << strength << " fade " << f;
      }
    }
  }
}

// ---- scene-format errors (SPEC 2) -----------------------------------------

std::string lightScene(const std::string& light) {
  return R"({"lightcts": 1, "image": {"width": 8, "height": 8},
    "camera": {"position": [0, 10, 0], "target": [0, 0, 0], "up": [0, 0, -1], "projection": "orthographic",
               "height": 10, "near": 0.1, "far": 100},
    "objects": [{"name": "floor", "mesh": {"type": "plane", "size": [10, 10], "subdivisions": 1}}],
    "lights": [)" + light + "]}";
}

// Loads `text`, expects a SceneLoadError whose message names one of `paths`.
void expectLoadError(const std::string& text, const std::vector<std::string>& paths) {
  try {
    scene_input::loadSceneText(text, "bad.json");
    ADD_FAILURE() << "loaded without error:\n" << text;
  } catch (const scene_input::SceneLoadError& e) {
    const std::string message = e.what();
    bool named = false;
    for (const std::string& p : paths) named = named || message.find(p) != std::string::npos;
    EXPECT_TRUE(named) << "message does not name " << paths.front() << ": " << message;
    EXPECT_NE(message.find("bad.json"), std::string::npos) << message;
    std::printf("[ scene error ] %s\n", message.c_str());
  }
}

TEST(ShadowIndependent, ShadowMapScenesThatAreErrors) {
  // A sanity scene that must load, so the failures below are the bullets'.
  EXPECT_NO_THROW(scene_input::loadSceneText(
      lightScene(R"({"type": "spot", "position": [0, 3, 0], "direction": [0, -1, 0], "range": 6,
        "spot_angle_deg": 170, "mode": "realtime", "shadows": true,
        "shadow_map": {"resolution": 128, "filter": "tent3x3", "near": 0.5}})"),
      "good.json"));

  // shadow_map on a mixed light (its shadows are baked, SPEC 3.5-3.6).
  expectLoadError(lightScene(R"({"type": "point", "position": [0, 3, 0], "range": 6, "mode": "mixed",
      "shadows": true, "shadow_map": {"resolution": 64}})"),
                  {"/lights/0/shadow_map"});
  // resolution not a power of two.
  expectLoadError(lightScene(R"({"type": "point", "position": [0, 3, 0], "range": 6, "mode": "realtime",
      "shadows": true, "shadow_map": {"resolution": 100}})"),
                  {"/lights/0/shadow_map/resolution"});
  // A shadowed spot wider than 170 degrees.
  expectLoadError(lightScene(R"({"type": "spot", "position": [0, 3, 0], "direction": [0, -1, 0], "range": 6,
      "spot_angle_deg": 175, "mode": "realtime", "shadows": true, "shadow_map": {"resolution": 64}})"),
                  {"/lights/0/shadow_map", "/lights/0/spot_angle_deg", "/lights/0/shadows"});
  // tent3x3 on a point light.
  expectLoadError(lightScene(R"({"type": "point", "position": [0, 3, 0], "range": 6, "mode": "realtime",
      "shadows": true, "shadow_map": {"filter": "tent3x3"}})"),
                  {"/lights/0/shadow_map/filter"});
  // near = range (near must lie in (0, range)).
  expectLoadError(lightScene(R"({"type": "spot", "position": [0, 3, 0], "direction": [0, -1, 0], "range": 6,
      "spot_angle_deg": 60, "mode": "realtime", "shadows": true, "shadow_map": {"near": 6}})"),
                  {"/lights/0/shadow_map"});
}

}  // namespace
