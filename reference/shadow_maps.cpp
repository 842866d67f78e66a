#include "reference/shadow_maps.h"

#include "lighting/light_space.h"
#include "reference/parallel_rows.h"
#include "reference/tolerance_model.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace reference {

using namespace lighting;
namespace tol = tolerance;

namespace {

constexpr double u = tol::kStepRoundoff;

HitFilter everyFace() {
  HitFilter filter;
  filter.frontFacesOnly = false;  // SPEC 3.9: both faces cast, no culling
  return filter;
}

// A closed interval of reals.
struct Range {
  double lo = 0, hi = 0;
  void include(double v) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
};

// The texels a tap (i, j) of view `view` reads: itself, clamped to the edge
// of a 2D map; across the edge on a cube; at a cube corner the three texels
// that meet there (a device may weigh them as it likes).
struct TapTexels {
  std::array<const ShadowTexel*, 3> texels{};
  int count = 0;
};

// SPEC 3.9's tent3x3 along one axis at x = mu N: the two fetches' weights and
// their coordinates in texels (fetch k at (c + offset_k) / N).
struct TentAxis {
  std::array<double, 2> weight{}, coordinate{};
};
TentAxis tentAxis(double x) {
  const double c = std::floor(x + 0.5), o = x - c;
  const double w0 = ((o + 0.5) * (o + 0.5) / 2 - o) * 4 / 9;
  const double w1 = ((1.5 - o) - 0.5 - std::min(o, 0.0) * std::min(o, 0.0)) * 4 / 9;
  const double w2 = ((1.5 + o) - 0.5 - std::max(o, 0.0) * std::max(o, 0.0)) * 4 / 9;
  const double w3 = ((o + 0.5) * (o + 0.5) / 2) * 4 / 9;
  TentAxis t;
  t.weight = {w0 + w1, w2 + w3};
  t.coordinate = {c + w1 / (w0 + w1) - 1.5, c + w3 / (w2 + w3) + 0.5};
  return t;
}

// The same at o within [oLo, oHi] of centre c: each fetch's weight and
// coordinate ranges. Each is monotone on o <= 0 and on o >= 0 (the pieces of
// min(o, 0)^2 and max(o, 0)^2), so the ends and 0 bound them.
struct TentAxisRange {
  std::array<Range, 2> weight, coordinate;
};
TentAxisRange tentAxisRange(double c, double oLo, double oHi) {
  TentAxisRange r;
  bool first = true;
  for (double o : {oLo, oHi, 0.0}) {
    if (o < oLo || o > oHi) continue;
    const TentAxis t = tentAxis(c + o);
    for (int k = 0; k < 2; ++k) {
      if (first) {
        r.weight[k] = {t.weight[k], t.weight[k]};
        r.coordinate[k] = {t.coordinate[k], t.coordinate[k]};
      } else {
        r.weight[k].include(t.weight[k]);
        r.coordinate[k].include(t.coordinate[k]);
      }
    }
    first = false;
  }
  return r;
}

}  // namespace

ReferenceShadowMap::ReferenceShadowMap(ShadowProjection projection, const Bvh& bvh, const Vec3& cameraPosition,
                                       int threads, int subPixelBits)
    : projection_(std::move(projection)), camera_(cameraPosition), resolution_(projection_.spec.resolution) {
  texels_.resize(projection_.views.size() * std::size_t(resolution_) * resolution_);
  for (int v = 0; v < viewCount(); ++v) buildView(v, bvh, threads, subPixelBits);
}

double ReferenceShadowMap::depthError(const ShadowView& view, const Vec3& q) const {
  const double position =
      tol::kShadowPositionSteps * u * (glm::length(q - camera_) + glm::length(view.origin - camera_));
  double slope;  // |d depth / d z_view|
  if (!view.perspective) {
    slope = 1.0 / (2.0 * view.halfWidth);
  } else {
    const double z = std::max(glm::dot(q - view.origin, view.f), view.nearPlane);
    slope = view.farPlane * view.nearPlane / ((view.farPlane - view.nearPlane) * z * z);
  }
  return tol::kDepthTieUlps * u + position * slope;
}

void ReferenceShadowMap::buildView(int v, const Bvh& bvh, int threads, int subPixelBits) {
  const ShadowView& view = projection_.views[v];
  const int n = resolution_;
  const WorldTriangles& world = bvh.world();
  // Pass 1: the nearest triangle at every texel centre, and which surface it is.
  // (object << 32) | piece, -1 none: imported meshes have any number of pieces.
  std::vector<std::int64_t> surface(std::size_t(n) * n, -1);
  std::vector<std::optional<RayHit>> hits(surface.size());
  forEachRow(n, threads, [&](int j) {
    for (int i = 0; i < n; ++i) {
      const std::size_t k = std::size_t(j) * n + i;
      const TexelRay t = view.rayThrough(texelCentre(i, n), texelCentre(j, n));
      hits[k] = bvh.nearestHit(t.ray, t.tMin, t.tMax, everyFace());
      ShadowTexel& texel = texels_[std::size_t(v) * n * n + k];
      if (hits[k]) {
        const WorldTriangle& tri = world.triangles[hits[k]->triangle];
        surface[k] = (std::int64_t(tri.object) << 32) | std::int64_t(std::uint32_t(tri.piece));
        texel.depth = std::clamp(view.project(t.ray.origin + hits[k]->t * t.ray.direction).depth, 0.0, 1.0);
      }
      texel.lo = texel.hi = texel.depth;
    }
  });
  // Pass 2: what a correct pass may store instead (docs/tolerances.md).
  forEachRow(n, threads, [&](int j) {
    for (int i = 0; i < n; ++i) {
      const std::size_t k = std::size_t(j) * n + i;
      ShadowTexel& texel = texels_[std::size_t(v) * n * n + k];
      const double mu = texelCentre(i, n), mv = texelCentre(j, n);
      const TexelRay centre = view.rayThrough(mu, mv);
      // The texel's size in world units at the hit, for the lateral share of
      // the vertices' position error.
      Vec3 q = centre.ray.origin + (hits[k] ? hits[k]->t : centre.tMax) * centre.ray.direction;
      const double texelWorld = 2.0 * view.halfWidth / n *
                                (view.perspective ? std::max(glm::dot(q - view.origin, view.f), view.nearPlane) : 1.0);
      const double lateral = tol::kShadowPositionSteps * u *
                             (glm::length(q - camera_) + glm::length(view.origin - camera_)) / texelWorld;
      Range depths{texel.depth, texel.depth};
      double error = hits[k] ? depthError(view, q) : 0.0;
      // The surface under a snapped centre: the hit triangle's plane at the
      // corners of the square the snapping may move the centre in.
      if (hits[k]) {
        const WorldTriangle& tri = world.triangles[hits[k]->triangle];
        const Vec3 normal = glm::cross(tri.p1 - tri.p0, tri.p2 - tri.p0);
        const double shift = (tol::vertexSnapPx(subPixelBits) + lateral) / n;
        const double shifts[4][2] = {{shift, shift}, {-shift, shift}, {shift, -shift}, {-shift, -shift}};
        for (const auto& s : shifts) {
          const TexelRay t = view.rayThrough(mu + s[0], mv + s[1]);
          const double facing = glm::dot(t.ray.direction, normal);
          const double along = facing != 0 ? glm::dot(tri.p0 - t.ray.origin, normal) / facing : -1.0;
          if (!(along > t.tMin)) depths.include(0.0);  // seen edge-on or clipped: anything nearer
          if (!(along > t.tMin) || along > t.tMax) {
            depths.include(1.0);
            continue;
          }
          depths.include(std::clamp(view.project(t.ray.origin + along * t.ray.direction).depth, 0.0, 1.0));
        }
      }
      // Near a change of surface: a snapped edge may give the texel the other side.
      bool neighbourDiffers = false;
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
          const int ni = i + di, nj = j + dj;
          if (ni >= 0 && nj >= 0 && ni < n && nj < n && surface[std::size_t(nj) * n + ni] != surface[k])
            neighbourDiffers = true;
        }
      if (neighbourDiffers) {
        constexpr int kProbes = 8;
        const double radius = (tol::edgeDistancePx(subPixelBits) + lateral) / n;
        for (int p = 0; p < kProbes; ++p) {
          const double angle = 2.0 * std::numbers::pi * p / kProbes;
          const TexelRay t = view.rayThrough(mu + radius * std::cos(angle), mv + radius * std::sin(angle));
          const auto hit = bvh.nearestHit(t.ray, t.tMin, t.tMax, everyFace());
          if (!hit) {
            depths.include(1.0);
            continue;
          }
          const Vec3 at = t.ray.origin + hit->t * t.ray.direction;
          depths.include(std::clamp(view.project(at).depth, 0.0, 1.0));
          error = std::max(error, depthError(view, at));
        }
      }
      texel.lo = std::max(0.0, depths.lo - error);
      texel.hi = std::min(1.0, depths.hi + error);
    }
  });
}

namespace {

// One view's lookup with the ranges of its inputs.
struct ViewLookup {
  const ReferenceShadowMap& map;
  int view;
  bool cube;
  Range depth;  // the receiver's depth

  // A coordinate this uncertain (texels) could read anything: not enumerated.
  static bool tooWide(Range r) { return !(r.hi - r.lo < 64); }

  TapTexels tap(int i, int j) const {
    const int n = map.resolution();
    TapTexels t;
    if (!cube) {
      t.texels[0] = &map.texel(view, std::clamp(i, 0, n - 1), std::clamp(j, 0, n - 1));
      t.count = 1;
      return t;
    }
    const CubeTexel c = cubeTexelAcrossEdge(view, i, j, n);
    t.texels[t.count++] = &map.texel(c.face, c.i, c.j);
    if (c.corner) {
      const CubeTexel a = cubeTexelAcrossEdge(view, c.i == 0 ? -1 : n, c.j, n);
      const CubeTexel b = cubeTexelAcrossEdge(view, c.i, c.j == 0 ? -1 : n, n);
      t.texels[t.count++] = &map.texel(a.face, a.i, a.j);
      t.texels[t.count++] = &map.texel(b.face, b.i, b.j);
    }
    return t;
  }

  // The compare's admissible results at one tap: [definitely lit, possibly lit].
  Range compare(int i, int j) const {
    const TapTexels t = tap(i, j);
    Range r{1, 0};
    for (int k = 0; k < t.count; ++k) {
      r.lo = std::min(r.lo, depth.hi <= t.texels[k]->lo ? 1.0 : 0.0);
      r.hi = std::max(r.hi, depth.lo <= t.texels[k]->hi ? 1.0 : 0.0);
    }
    return r;
  }

  // A bilinear compare with its coordinate in x = mu N - 0.5 (texel units)
  // anywhere in [x.lo, x.hi] (likewise y) and each weight off by `weight`.
  Range bilinear(Range x, Range y, double weight) const {
    if (tooWide(x) || tooWide(y)) return {0, 1};
    Range out{1e300, -1e300};
    for (int i0 = int(std::floor(x.lo)); i0 <= int(std::floor(x.hi)); ++i0)
      for (int j0 = int(std::floor(y.lo)); j0 <= int(std::floor(y.hi)); ++j0) {
        const double aLo = std::max(0.0, std::max(x.lo - i0, 0.0) - weight);
        const double aHi = std::min(1.0, std::min(x.hi - i0, 1.0) + weight);
        const double bLo = std::max(0.0, std::max(y.lo - j0, 0.0) - weight);
        const double bHi = std::min(1.0, std::min(y.hi - j0, 1.0) + weight);
        const Range c00 = compare(i0, j0), c10 = compare(i0 + 1, j0);
        const Range c01 = compare(i0, j0 + 1), c11 = compare(i0 + 1, j0 + 1);
        // Bilinear in (a, b) and linear in each compare: the extremes lie at
        // the corners of the weight box, with the compares' own extremes.
        for (double a : {aLo, aHi})
          for (double b : {bLo, bHi}) {
            const double w00 = (1 - a) * (1 - b), w10 = a * (1 - b), w01 = (1 - a) * b, w11 = a * b;
            out.lo = std::min(out.lo, w00 * c00.lo + w10 * c10.lo + w01 * c01.lo + w11 * c11.lo);
            out.hi = std::max(out.hi, w00 * c00.hi + w10 * c10.hi + w01 * c01.hi + w11 * c11.hi);
          }
      }
    return out;
  }

  Range hard(Range x, Range y) const {
    if (tooWide(x) || tooWide(y)) return {0, 1};
    const int n = map.resolution();
    Range out{1e300, -1e300};
    // mu = 1 exactly reads the last texel (clamp to edge).
    auto last = [&](double v) { return cube ? int(std::floor(v)) : std::min(int(std::floor(v)), n - 1); };
    for (int i = last(x.lo); i <= last(x.hi); ++i)
      for (int j = last(y.lo); j <= last(y.hi); ++j) {
        const Range c = compare(i, j);
        out.lo = std::min(out.lo, c.lo);
        out.hi = std::max(out.hi, c.hi);
      }
    return out;
  }

  // x, y: mu N and mv N.
  Range tent(Range x, Range y, double weight) const {
    Range out{1e300, -1e300};
    auto centres = [](Range r) { return std::pair{std::floor(r.lo + 0.5), std::floor(r.hi + 0.5)}; };
    const auto [cxLo, cxHi] = centres(x);
    const auto [cyLo, cyHi] = centres(y);
    const double slack = tol::kShadowTentWeightSteps * u;
    for (double cx = cxLo; cx <= cxHi; ++cx)
      for (double cy = cyLo; cy <= cyHi; ++cy) {
        const TentAxisRange ax = tentAxisRange(cx, std::max(x.lo - cx, -0.5), std::min(x.hi - cx, 0.5));
        const TentAxisRange ay = tentAxisRange(cy, std::max(y.lo - cy, -0.5), std::min(y.hi - cy, 0.5));
        // The four fetches' weights each lie in [low, high] and sum to 1 (up
        // to their roundings): the lowest s gives every fetch its lowest
        // weight and the rest of the unit mass to the lowest fetch; the
        // highest likewise from the top. A uniform region stays exactly 1 or 0.
        std::array<Range, 4> weights, fetches;
        for (int kx = 0; kx < 2; ++kx)
          for (int ky = 0; ky < 2; ++ky) {
            const int k = 2 * kx + ky;
            fetches[k] = bilinear({ax.coordinate[kx].lo - 0.5 - slack, ax.coordinate[kx].hi - 0.5 + slack},
                                  {ay.coordinate[ky].lo - 0.5 - slack, ay.coordinate[ky].hi - 0.5 + slack}, weight);
            weights[k] = {std::max(0.0, ax.weight[kx].lo - slack) * std::max(0.0, ay.weight[ky].lo - slack),
                          (ax.weight[kx].hi + slack) * (ay.weight[ky].hi + slack)};
          }
        double lowMass = 0, highMass = 0, lowest = 1, lowestHigh = 1;
        Range sum{0, 0};
        for (int k = 0; k < 4; ++k) {
          sum.lo += weights[k].lo * fetches[k].lo;
          sum.hi += weights[k].hi * fetches[k].hi;
          lowMass += weights[k].lo;
          highMass += weights[k].hi;
          lowest = std::min(lowest, fetches[k].lo);
          lowestHigh = std::min(lowestHigh, fetches[k].hi);
        }
        sum.lo += std::max(0.0, 1.0 - lowMass) * lowest - slack;
        sum.hi -= std::max(0.0, highMass - 1.0) * lowestHigh - slack;
        out.lo = std::min(out.lo, std::max(0.0, sum.lo));
        out.hi = std::max(out.hi, std::min(1.0, sum.hi));
      }
    return out;
  }
};

}  // namespace

double ReferenceShadowMap::value(const Vec3& p, const Vec3& N) const {
  const Vec3 q = projection_.offsetReceiver(p, N);
  const int v = projection_.viewOf(q);
  const MapPoint m = projection_.views[v].project(q);
  if (m.outsideMap()) return 1.0;
  const int n = resolution_;
  const bool cube = projection_.type == LightType::Point;
  // The nominal compare: a cube corner reads the mean of its three texels.
  auto lit = [&](int i, int j) {
    const ViewLookup look{*this, v, cube, {m.depth, m.depth}};
    const TapTexels t = look.tap(i, j);
    double sum = 0;
    for (int k = 0; k < t.count; ++k) sum += m.depth <= t.texels[k]->depth ? 1.0 : 0.0;
    return sum / t.count;
  };
  auto bilinearAt = [&](double x, double y) {  // x = mu N - 0.5
    const int i0 = int(std::floor(x)), j0 = int(std::floor(y));
    const double a = x - i0, b = y - j0;
    return (1 - a) * (1 - b) * lit(i0, j0) + a * (1 - b) * lit(i0 + 1, j0) + (1 - a) * b * lit(i0, j0 + 1) +
           a * b * lit(i0 + 1, j0 + 1);
  };
  switch (projection_.spec.filter) {
    case ShadowFilter::Hard:
      return lit(std::min(int(std::floor(m.mu * n)), n - 1), std::min(int(std::floor(m.mv * n)), n - 1));
    case ShadowFilter::Bilinear: return bilinearAt(m.mu * n - 0.5, m.mv * n - 0.5);
    case ShadowFilter::Tent3x3: {
      const TentAxis ax = tentAxis(m.mu * n), ay = tentAxis(m.mv * n);
      double s = 0;
      for (int kx = 0; kx < 2; ++kx)
        for (int ky = 0; ky < 2; ++ky)
          s += ax.weight[kx] * ay.weight[ky] * bilinearAt(ax.coordinate[kx] - 0.5, ay.coordinate[ky] - 0.5);
      return s;
    }
  }
  return 1.0;
}

ShadowLookup ReferenceShadowMap::lookup(const Vec3& p, const Vec3& N, const LookupError& error,
                                        double weightPrecision) const {
  ShadowLookup out;
  out.s = out.lo = out.hi = value(p, N);
  const Vec3 q = projection_.offsetReceiver(p, N);
  const ShadowMapSpec& spec = projection_.spec;
  // The float32 p' (docs/tolerances.md "Shadow maps"): p's own error, the
  // light transform's as a position error, and the biases times their
  // directions' errors (L turns by the position error over the distance).
  const double toLight =
      projection_.type == LightType::Directional ? 1e300 : std::max(glm::length(projection_.lightPosition - p), 1e-300);
  const Vec3 origin = projection_.views[0].origin;
  const double e = error.position +
                   tol::kShadowPositionSteps * u * (glm::length(q - camera_) + glm::length(origin - camera_)) +
                   spec.depthBias * (error.position / toLight + tol::kNormalizedDirectionSteps * u) +
                   spec.normalBias * (tol::kNormalInterpolationSteps + tol::kNormalizedDirectionSteps) * u;
  std::array<Vec3, 7> points;
  points[0] = q;
  for (int axis = 0; axis < 3; ++axis)
    for (int sign = 0; sign < 2; ++sign) {
      points[1 + 2 * axis + sign] = q;
      points[1 + 2 * axis + sign][axis] += sign ? e : -e;
    }
  // The receiver's further move that only the compares see: its depth
  // range grows by the points of the larger cube.
  std::array<Vec3, 6> depthPoints;
  for (int axis = 0; axis < 3; ++axis)
    for (int sign = 0; sign < 2; ++sign) {
      depthPoints[2 * axis + sign] = q;
      depthPoints[2 * axis + sign][axis] += sign ? e + error.depthOnlyMove : -(e + error.depthOnlyMove);
    }
  const bool cube = projection_.type == LightType::Point;
  std::array<bool, kCubeFaceCount> views{};
  for (const Vec3& point : points) views[projection_.viewOf(point)] = true;
  const int n = resolution_;
  const double slack = tol::kShadowCoordinateSteps * u;
  for (int v = 0; v < viewCount(); ++v) {
    if (!views[v]) continue;
    const ShadowView& view = projection_.views[v];
    Range mu{1e300, -1e300}, mv{1e300, -1e300}, depth{1e300, -1e300};
    bool anyOutside = false, anyInside = false;
    for (const Vec3& point : points) {
      const MapPoint m = view.project(point);
      // A cube face's neighbours continue it: only depth leaves a cube.
      const bool outside = cube ? (m.behind || m.depth < 0 || m.depth > 1) : m.outsideMap();
      (outside ? anyOutside : anyInside) = true;
      if (m.behind) continue;
      mu.include(m.mu);
      mv.include(m.mv);
      depth.include(m.depth);
    }
    if (error.depthOnlyMove > 0)
      for (const Vec3& point : depthPoints) {
        const MapPoint m = view.project(point);
        if (!m.behind) depth.include(m.depth);
      }
    if (anyOutside) {
      out.lo = std::min(out.lo, 1.0);
      out.hi = std::max(out.hi, 1.0);
    }
    if (!anyInside) continue;
    // Inside the map: clamp the ranges to it (past the edge is the outside above).
    auto clampRange = [&](Range r, bool toMap) {
      r.lo -= slack;
      r.hi += slack;
      if (toMap) r = {std::clamp(r.lo, 0.0, 1.0), std::clamp(r.hi, 0.0, 1.0)};
      return r;
    };
    mu = clampRange(mu, !cube);
    mv = clampRange(mv, !cube);
    depth = clampRange(depth, true);
    const ViewLookup look{*this, v, cube, depth};
    Range s;
    switch (spec.filter) {
      case ShadowFilter::Hard: s = look.hard({mu.lo * n, mu.hi * n}, {mv.lo * n, mv.hi * n}); break;
      case ShadowFilter::Bilinear:
        s = look.bilinear({mu.lo * n - 0.5, mu.hi * n - 0.5}, {mv.lo * n - 0.5, mv.hi * n - 0.5}, weightPrecision);
        break;
      case ShadowFilter::Tent3x3:
        s = look.tent({mu.lo * n, mu.hi * n}, {mv.lo * n, mv.hi * n}, weightPrecision);
        break;
    }
    out.lo = std::min(out.lo, s.lo);
    out.hi = std::max(out.hi, s.hi);
  }
  out.lo = std::clamp(out.lo, 0.0, 1.0);
  out.hi = std::clamp(out.hi, 0.0, 1.0);
  return out;
}

imaging::Image ReferenceShadowMap::viewImage(int view) const {
  imaging::Image image(resolution_, resolution_, 3);
  for (int j = 0; j < resolution_; ++j)
    for (int i = 0; i < resolution_; ++i) {
      const ShadowTexel& t = texel(view, i, j);
      image.at(i, j, 0) = float(t.depth);
      image.at(i, j, 1) = float(t.lo);
      image.at(i, j, 2) = float(t.hi);
    }
  return image;
}

}  // namespace reference
