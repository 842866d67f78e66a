#include "reference/reference_renderer.h"

#include "lighting/brdf.h"
#include "reference/baked_lights_realtime.h"
#include "reference/deferred_buffers.h"
#include "reference/light_evaluation.h"
#include "reference/lightmap_sampling.h"
#include "reference/parallel_rows.h"
#include "reference/surface_inputs.h"
#include "reference/tolerance_model.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <numbers>
#include <optional>

namespace reference {

using namespace lighting;
namespace tol = tolerance;

namespace {

// What a pixel centre sees: an object's smooth piece, or the background.
struct SurfaceKey {
  int object = -1;
  int piece = 0;
  bool operator==(const SurfaceKey&) const = default;
};

struct Shaded {
  Vec3 value{0.0};  // double, before any rounding
  Vec3 bound{0.0};
  // Against real time only: |bilinear of the texel-centre irradiance - the
  // irradiance here| (RealtimeBakedLights::Sample::interpolation). A GPU
  // samples the map at a snapped point, so the pixel takes the largest of
  // this over the centre and its sub-pixel shifts.
  Vec3 interpolation{0.0};
  // What the lights add to `value`: all of it but A * (ambient + lightmap).
  Vec3 lights{0.0};
  // The shadowed lights' change over the snapping square where a shadow
  // edge crosses it (LightSum::shadowEdgeChange), with the material's colours.
  Vec3 shadowEdgeChange{0.0};
  int evaluations = 0;
  bool shadowed = false;        // LightSum::shadowed (SPEC 3.9)
  double widestShadowSpan = 0;  // LightSum::widestShadowSpan, and its interval
  double widestShadowLo = 1, widestShadowHi = 1;
};

// How far the float32 diffuse colour and F0 of an srp material may be from
// SPEC 3.8's (tolerance_model.h); Lambert's A is the albedo the bound of the
// combine already counts.
struct BrdfColourErrors {
  Vec3 diffuse{0.0}, specular{0.0};
};
BrdfColourErrors brdfColourErrors(const Object& object) {
  BrdfColourErrors e;
  if (object.brdf != Brdf::Srp) return e;
  const double u = tol::kStepRoundoff, m = object.metallic;
  const Vec3& A = object.albedo;
  e.diffuse = A * ((1.0 - kMinReflectivity) * (tol::kDiffuseColourSteps * u * (1.0 - m) + u * m));
  e.specular = glm::max(A, Vec3(kMinReflectivity)) * (tol::kSpecularColourSteps * u) +
               glm::abs(A - Vec3(kMinReflectivity)) * (u * m);
  return e;
}

// How far vertex snapping may move the surface point a pixel centre sees
// (tolerance_model.h), along the surface: the diagonal of the square of
// half-side `vertexSnap` pixels across the view axis at p's depth, stretched
// by the surface's slope to the ray. A surface seen edge-on would stretch it
// without end; below a cosine of 1e-3 (0.06 degrees from edge-on) it is held
// at 1000 times the square, which already takes every factor of the light
// terms to the top of its range (light_evaluation.cpp).
double snappedSurfaceMove(const CameraView& view, const Vec3& p, const Vec3& faceNormal, double vertexSnap) {
  constexpr double kSmallestFacing = 1e-3;
  const Vec3 toPoint = p - view.camera.position;
  const Vec3 ray = view.camera.projection == Projection::Perspective && glm::length(toPoint) > 0
                       ? glm::normalize(toPoint)
                       : view.forward;
  const double facing =
      glm::length(faceNormal) > 0 ? std::abs(glm::dot(ray, glm::normalize(faceNormal))) : 1.0;
  return std::numbers::sqrt2 * vertexSnap * view.pixelSizeAt(p) / std::max(facing, kSmallestFacing);
}

// Everything about a frame that does not change from pixel to pixel.
struct FrameShading {
  const Frame& frame;
  const WorldTriangles& world;
  const Bvh& bvh;
  // SPEC 3.9: the frame's reference shadow maps, or ray-traced visibility (--ideal).
  std::vector<std::unique_ptr<ReferenceShadowMap>> shadowMaps;
  RealtimeShadows realtimeShadows;
  LightEvaluator evaluator;
  std::vector<ObjectLights> lights;       // per object
  std::vector<PositionContext> contexts;  // per object
  std::vector<const ObjectBake*> bakes;   // per object: its maps, or null (SPEC 3.5, 3.6)
  std::vector<MaterialBrdf> materials;    // per object (SPEC 3.8; Lambert: diffuse = A, no lobe)
  std::vector<BrdfColourErrors> colourErrors;  // per object
  std::optional<RealtimeBakedLights> realtimeBaked;  // ReferenceOptions::bakedLightsRealtime
  std::vector<Vec3> vertexValue;          // per world vertex: legacy vertex lights (SPEC 4)
  std::vector<Vec3> vertexBound;
  glm::dmat4 viewProjection;     // camera-relative world to clip, as the GPU gets it
  double nearestClipW;           // the near plane's clip w (1 orthographic)
  double filterWeightPrecision;  // ReferenceOptions::filterWeightPrecision
  double vertexSnap;             // tolerance::vertexSnapPx of ReferenceOptions::subPixelPrecisionBits

  FrameShading(const Frame& f, const WorldTriangles& w, const Bvh& b, const ReferenceOptions& options,
               std::vector<std::unique_ptr<ReferenceShadowMap>> maps)
      : frame(f),
        world(w),
        bvh(b),
        shadowMaps(std::move(maps)),
        realtimeShadows(realtimeShadowsOf(f, b, shadowMaps, options)),
        // The fade weights are part of the budgets: `--ideal` has neither.
        evaluator(f.scene(), f.scene().pipeline.profile,
                  options.ideal ? std::vector<double>{} : f.selection.weightsBySceneLight(f.scene().lights.size()),
                  f.prepared->shadowMask.channelOfLight, options.filterWeightPrecision, &realtimeShadows),
        viewProjection(f.view.cameraRelativeViewProjection()),
        nearestClipW(f.view.camera.projection == Projection::Perspective ? f.view.camera.nearPlane : 1.0),
        filterWeightPrecision(options.filterWeightPrecision),
        vertexSnap(tol::vertexSnapPx(options.subPixelPrecisionBits)) {
    const auto& objects = f.prepared->objects;
    for (int o = 0; o < int(objects.size()); ++o) {
      lights.push_back(options.ideal ? f.idealLightsForObject() : f.lightsForObject(o));
      bakes.push_back(f.prepared->bakeOf(o));  // throws for a scene that needs a bake it did not get
      materials.push_back(materialBrdf(f.scene().objects[o]));
      colourErrors.push_back(brdfColourErrors(f.scene().objects[o]));
      const BoundingSphere& bounds = objects[o].bounds;
      contexts.push_back({f.view.camera.position, glm::length(bounds.centre - f.view.camera.position) + bounds.radius});
    }
    if (options.bakedLightsRealtime) realtimeBaked.emplace(*f.prepared, b, options.threads);
    // Vertex lights are evaluated at the vertices with the rotated, normalised
    // vertex normal, then interpolated with the hit's barycentrics. They get
    // no shadow mask: the GPU's vertex stage passes a mask of 1.
    vertexValue.assign(w.vertices.size(), Vec3(0.0));
    vertexBound.assign(w.vertices.size(), Vec3(0.0));
    for (std::size_t v = 0; v < w.vertices.size(); ++v) {
      const WorldVertex& vertex = w.vertices[v];
      const std::vector<int>& perVertex = lights[vertex.object].perVertex;
      if (perVertex.empty()) continue;
      LightSum sum;
      // The vertex stage's own position and normal (reference/surface_inputs.h).
      const SurfaceErrors inputs = vertexInputErrors(f.prepared->objects[vertex.object].transform,
                                                     f.view.camera.position, {vertex.local, vertex.localNormal});
      PositionContext where = contexts[vertex.object];
      where.inputs = &inputs;
      evaluator.accumulate(perVertex, vertex.position, vertex.normal, where, sum);
      vertexValue[v] = sum.value;
      vertexBound[v] = sum.errorBound;
    }
  }

  static RealtimeShadows realtimeShadowsOf(const Frame& f, const Bvh& b,
                                           const std::vector<std::unique_ptr<ReferenceShadowMap>>& maps,
                                           const ReferenceOptions& options) {
    RealtimeShadows shadows;
    shadows.shadowDistance = f.scene().pipeline.shadowDistance;
    if (options.ideal) shadows.idealVisibility = &b;  // SPEC 3.9 `--ideal`: exact visibility
    for (const auto& map : maps) shadows.mapOfLight.push_back(map.get());
    return shadows;
  }

  // SPEC 3.8's V at p, with its float32 error: a camera-relative
  // implementation normalises -p, off by the position error over |p - camera|
  // (docs/tolerances.md "Specular lobe"); orthographic V is the uploaded
  // float(-forward), one rounding per component.
  LobeAtPoint lobeAt(const Vec3& p, const PositionContext& where, double smoothness) const {
    const double u = tol::kStepRoundoff;
    LobeAtPoint lobe;
    lobe.view = viewDirection(frame.view, p);
    lobe.smoothness = smoothness;
    // The interpolation turns the normal before normalize() does its part.
    lobe.normalError = {tol::kNormalizedLengthSteps * u,
                        (tol::kNormalInterpolationSteps + tol::kNormalizedDirectionSteps) * u};
    if (frame.view.camera.projection == Projection::Orthographic) {
      lobe.viewError = {tol::kNormalizedDirectionSteps * u, tol::kNormalizedDirectionSteps * u};
    } else {
      const double distance = glm::length(p - where.camera);
      const double positionError = where.reconstructionError > 0 ? where.reconstructionError
                                                                 : std::sqrt(3.0) * where.inputs->position;
      lobe.viewError = {tol::kNormalizedLengthSteps * u,
                        std::min(2.0, positionError / distance + tol::kNormalizedDirectionSteps * u)};
    }
    return lobe;
  }

  // Clipping range along a ray: view depth in [near, far].
  void depthRange(const Ray& ray, double& tMin, double& tMax) const {
    const double cosine = glm::dot(ray.direction, frame.view.forward);
    tMin = frame.view.camera.nearPlane / cosine;
    tMax = frame.view.camera.farPlane / cosine;
  }

  std::optional<RayHit> trace(const Ray& ray) const {
    double tMin, tMax;
    depthRange(ray, tMin, tMax);
    return bvh.nearestHit(ray, tMin, tMax);
  }

  SurfaceKey keyOf(const std::optional<RayHit>& hit) const {
    if (!hit) return {};
    const WorldTriangle& t = world.triangles[hit->triangle];
    return {t.object, t.piece};
  }

  // Whether `other` (the hit of `ray`) lies on the surface the centre's
  // `hit` does: the same smooth piece, and no jump in depth from it. A piece
  // may fold over itself (a fillet in front of a face of the same piece):
  // where `ray` meets the centre triangle's plane and where it hits may then
  // be far apart. A jump is a gap of more than two pixel footprints along the
  // ray (more at grazing angles), far above what curvature gives a probe a
  // fraction of a pixel away.
  bool sameSurface(const std::optional<RayHit>& hit, const std::optional<RayHit>& other, const Ray& ray) const {
    if (!(keyOf(hit) == keyOf(other))) return false;
    if (!hit || hit->triangle == other->triangle) return true;
    const WorldTriangle& t = world.triangles[hit->triangle];
    const Vec3 normal = glm::normalize(glm::cross(t.p1 - t.p0, t.p2 - t.p0));
    const double facing = std::abs(glm::dot(normal, ray.direction));
    if (facing < 1e-9) return false;
    const double tPlane = glm::dot(normal, t.p0 - ray.origin) / glm::dot(normal, ray.direction);
    const Vec3 p = ray.origin + other->t * ray.direction;
    return std::abs(other->t - tPlane) <= 2.0 * frame.view.pixelSizeAt(p) / std::max(facing, 0.05);
  }

  // Whether the pixel point (px, py) lies within `distancePx` of an open
  // edge of the hit triangle (WorldTriangle::openEdges), on screen; the part
  // of an edge nearer than the near plane is cut off, as the clipper does.
  bool nearOpenEdge(const RayHit& hit, double px, double py, double distancePx) const {
    const WorldTriangle& t = world.triangles[hit.triangle];
    if (t.openEdges == 0) return false;
    const glm::dmat4 clipOf = frame.view.cameraRelativeViewProjection();
    const double nearW = frame.view.camera.projection == Projection::Perspective ? frame.view.camera.nearPlane : 1.0;
    const Vec3 corners[3] = {t.p0, t.p1, t.p2};
    glm::dvec4 clip[3];
    for (int i = 0; i < 3; ++i) clip[i] = clipOf * glm::dvec4(corners[i] - frame.view.camera.position, 1.0);
    auto screenOf = [&](const glm::dvec4& c) {
      return glm::dvec2((c.x / c.w + 1.0) * 0.5 * frame.view.width, (1.0 - c.y / c.w) * 0.5 * frame.view.height);
    };
    const glm::dvec2 point(px, py);
    for (int i = 0; i < 3; ++i) {
      if (!(t.openEdges & (1u << i))) continue;
      glm::dvec4 ca = clip[i], cb = clip[(i + 1) % 3];
      if (ca.w < nearW && cb.w < nearW) continue;
      if (ca.w < nearW) ca += (nearW - ca.w) / (cb.w - ca.w) * (cb - ca);
      if (cb.w < nearW) cb += (nearW - cb.w) / (ca.w - cb.w) * (ca - cb);
      const glm::dvec2 a = screenOf(ca), ab = screenOf(cb) - a;
      const double length2 = glm::dot(ab, ab);
      const double along = length2 > 0 ? std::clamp(glm::dot(point - a, ab) / length2, 0.0, 1.0) : 0.0;
      if (glm::length(point - (a + along * ab)) <= distancePx) return true;
    }
    return false;
  }

  // `withBound` false: the value alone (a shifted point of the sub-pixel
  // term, whose bound nothing reads).
  Shaded shade(const RayHit& hit, bool withBound = true) const {
    const WorldTriangle& tri = world.triangles[hit.triangle];
    const double b0 = 1.0 - hit.b1 - hit.b2;
    const Vec3 p = b0 * tri.p0 + hit.b1 * tri.p1 + hit.b2 * tri.p2;
    const Vec3& n0 = world.vertices[tri.vertex[0]].normal;
    const Vec3& n1 = world.vertices[tri.vertex[1]].normal;
    const Vec3& n2 = world.vertices[tri.vertex[2]].normal;
    const Vec3 N = glm::normalize(b0 * n0 + hit.b1 * n1 + hit.b2 * n2);

    // SPEC 3.5, 3.6: the object's maps at the hit's lightmap UV.
    const ObjectBake* bake = bakes[tri.object];
    ShadowMaskAtPoint mask;
    Vec3 baked(0.0), bakedBound(0.0), interpolation(0.0);
    if (bake) {
      const Object& object = frame.scene().objects[tri.object];
      const Vec2 uv = lightmapUvOfWorldPoint(object.mesh, frame.prepared->objects[tri.object].transform, p);
      if (!bake->shadowMask.empty()) {
        const BilinearSample m = sampleBilinear(bake->shadowMask, uv);
        mask.value = m.value;
        mask.error = filteringErrorBound(m, bake->shadowMask.resolution, filterWeightPrecision);
      }
      if (realtimeBaked) {
        const RealtimeBakedLights::Sample e = realtimeBaked->sample(tri.object, p, N, uv);
        baked = e.value;
        bakedBound = e.allowance - e.interpolation;
        interpolation = e.interpolation;
      } else if (!bake->lightmap.empty()) {
        const BilinearSample e = sampleBilinear(bake->lightmap, uv);
        const Vec4 bound = filteringErrorBound(e, bake->lightmap.resolution, filterWeightPrecision);
        baked = Vec3(e.value);
        bakedBound = Vec3(bound);
      }
    }

    const Scene& scene = frame.scene();
    const bool deferred = scene.pipeline.path == RenderPath::Deferred;
    PositionContext where = contexts[tri.object];
    where.snapMove = snappedSurfaceMove(frame.view, p, glm::cross(tri.p1 - tri.p0, tri.p2 - tri.p0), vertexSnap);
    // What the fragment stage gets at this point: the vertex stage's outputs
    // blended as the rasteriser does (reference/surface_inputs.h).
    SurfaceErrors inputs;
    if (withBound) {
      std::array<MeshVertex, 3> meshVertices;
      for (int k = 0; k < 3; ++k)
        meshVertices[k] = {world.vertices[tri.vertex[k]].local, world.vertices[tri.vertex[k]].localNormal};
      inputs = fragmentInputErrors(frame.prepared->objects[tri.object].transform, frame.view.camera.position,
                                   viewProjection, nearestClipW, meshVertices, {b0, hit.b1, hit.b2});
    }
    where.inputs = &inputs;
    where.valueOnly = !withBound;
    if (deferred) where.reconstructionError = reconstructionPositionError(frame.view, p, vertexSnap);
    const MaterialBrdf& brdf = materials[tri.object];
    std::optional<LobeAtPoint> lobe;
    if (brdf.lobe) lobe = lobeAt(p, where, scene.objects[tri.object].smoothness);
    // SPEC 3.9's fade reads the view depth, off by the position error (the
    // deferred pass's is its reconstruction's).
    const ShadowReceiver receiver{frame.view.viewDepth(p),
                                  deferred ? where.reconstructionError : std::sqrt(3.0) * inputs.position};
    LightSum sum;
    evaluator.accumulate(lights[tri.object].perPixel, p, N, where, sum,
                         bake && !bake->shadowMask.empty() ? &mask : nullptr, lobe ? &*lobe : nullptr, &receiver);
    if (!lights[tri.object].perVertex.empty()) {
      sum.value += b0 * vertexValue[tri.vertex[0]] + hit.b1 * vertexValue[tri.vertex[1]] +
                   hit.b2 * vertexValue[tri.vertex[2]];
      sum.errorBound += b0 * vertexBound[tri.vertex[0]] + hit.b1 * vertexBound[tri.vertex[1]] +
                        hit.b2 * vertexBound[tri.vertex[2]];
    }
    // SPEC 3: colour = A * ambient + A * lightmap(p) + the light sums; SPEC
    // 3.8 (srp): diffuse for A, and F0 times the sum of the lobes.
    const Vec3 unlit = scene.ambient + baked;
    Shaded shaded;
    shaded.value = brdf.diffuse * (unlit + sum.value) + brdf.specular * sum.specular;
    const double combineSteps = tol::kFinalCombineSteps + (bake ? tol::kLightmapAddRoundingSteps : 0.0) +
                                (brdf.lobe ? tol::kSpecularTermSteps : 0.0);
    const BrdfColourErrors& colourError = colourErrors[tri.object];
    shaded.bound = brdf.diffuse * (sum.errorBound + bakedBound) + brdf.specular * sum.specularBound +
                   colourError.diffuse * (unlit + sum.value) + colourError.specular * sum.specular +
                   glm::abs(shaded.value) * (combineSteps * tol::kStepRoundoff);
    if (deferred) applyDeferredBuffer(scene.pipeline.deferredBuffer, brdf, sum, shaded);
    shaded.lights = shaded.value - brdf.diffuse * unlit;
    shaded.shadowEdgeChange = brdf.diffuse * sum.shadowEdgeChange;
    shaded.interpolation = brdf.diffuse * interpolation;
    shaded.evaluations = sum.evaluations;
    shaded.shadowed = sum.shadowed;
    shaded.widestShadowSpan = sum.widestShadowSpan;
    shaded.widestShadowLo = sum.widestShadowLo;
    shaded.widestShadowHi = sum.widestShadowHi;
    return shaded;
  }

  // SPEC 3.7: the light sum goes through the light buffer. `shaded` holds
  // the forward value and bound; the light part A * sum is replaced by what
  // the buffer decodes to, with the buffer's own error (deferred_buffers.h).
  static void applyDeferredBuffer(DeferredBuffer buffer, const MaterialBrdf& brdf, const LightSum& sum,
                                  Shaded& shaded) {
    const Vec3 light = brdf.diffuse * sum.value + brdf.specular * sum.specular;
    // Albedo times each light's term before the blend: one rounding per term.
    shaded.bound += glm::abs(light) * (tol::kDeferredAlbedoProductSteps * tol::kStepRoundoff);
    for (int c = 0; c < 3; ++c) {
      // A light adds nothing in a channel whose diffuse colour and F0 are 0:
      // exp2(-0) = 1, + 0.
      const bool adds = brdf.diffuse[c] > 0 || (brdf.lobe && brdf.specular[c] > 0);
      const int contributing = adds ? int(sum.contributing[c]) : 0;
      if (buffer == DeferredBuffer::Hdr16) shaded.bound[c] += hdr16BlendBound(light[c], contributing);
      if (buffer == DeferredBuffer::Ldr8) {
        shaded.value[c] += decodedLightSum(buffer, light[c]) - light[c];
        // The light sum's arithmetic bound acts inside the encoding: the
        // decode bound carries it (and clamps it at saturation).
        const double sumBound = brdf.diffuse[c] * sum.errorBound[c] + brdf.specular[c] * sum.specularBound[c];
        shaded.bound[c] += ldr8DecodeBound(light[c], contributing, sumBound) - sumBound;
      }
    }
  }

  // Depth-buffer resolution in view depth at depth z (SPEC 7: D32F, LESS).
  double depthResolution(double z, const Vec3& p) const {
    const Camera& c = frame.view.camera;
    const double storedUlp = tol::kDepthTieUlps * tol::kStepRoundoff;
    const double fromBuffer = c.projection == Projection::Perspective
                                  ? storedUlp * z * z * (c.farPlane - c.nearPlane) / (c.farPlane * c.nearPlane)
                                  : storedUlp * (c.farPlane - c.nearPlane);
    const double fromPosition = tol::kPositionRoundingSteps * tol::kStepRoundoff * glm::length(p - c.position);
    return fromBuffer + fromPosition;
  }

  // True when another surface lies within depth precision of the hit, or the
  // hit lies within it of the near or far plane: either may win on a GPU.
  bool depthIsAmbiguous(const Ray& ray, const RayHit& hit) const {
    const WorldTriangle& tri = world.triangles[hit.triangle];
    const Vec3 p = ray.origin + hit.t * ray.direction;
    const double cosine = glm::dot(ray.direction, frame.view.forward);
    const double z = hit.t * cosine;
    const double dz = depthResolution(z, p);
    const Camera& c = frame.view.camera;
    if (z - c.nearPlane <= dz || c.farPlane - z <= dz) return true;
    double tMin, tMax;
    depthRange(ray, tMin, tMax);
    HitFilter other;
    other.excludeObject = tri.object;
    other.excludePiece = tri.piece;
    return bvh.nearestHit(ray, tMin, hit.t + dz / cosine, other).has_value();
  }
};

constexpr int kEdgeProbes = 8;

}  // namespace

bool readsFilteredTextures(const lighting::PreparedScene& prepared) {
  if (prepared.needsBake()) return true;
  for (const lighting::Light& light : prepared.scene.lights)
    if (light.cookie || light.shadowMap) return true;
  return false;
}

ReferenceRenderer::ReferenceRenderer(std::shared_ptr<const PreparedScene> prepared)
    : prepared_(std::move(prepared)), world_(buildWorldTriangles(*prepared_)), bvh_(world_) {}

bool ReferenceImages::shadowAmbiguityExceedsCap() const {
  return double(ambiguousShadowPixels) > tol::kMostAmbiguousShadowFraction * double(shadowedPixels);
}

std::vector<std::unique_ptr<ReferenceShadowMap>> ReferenceRenderer::shadowMaps(const Frame& frame, int threads,
                                                                               int subPixelBits) const {
  const Scene& scene = frame.scene();
  std::vector<std::unique_ptr<ReferenceShadowMap>> maps(scene.lights.size());
  for (int l = 0; l < int(scene.lights.size()); ++l) {
    if (!scene.lights[l].shadowMap) continue;
    maps[l] = std::make_unique<ReferenceShadowMap>(shadowProjection(scene, l), bvh_, frame.view.camera.position,
                                                   threads, subPixelBits);
  }
  return maps;
}

std::optional<VisibleSurface> ReferenceRenderer::visibleSurface(const Frame& frame, int x, int y) const {
  const Ray ray = frame.view.rayThroughPixel(x + 0.5, y + 0.5);
  const double cosine = glm::dot(ray.direction, frame.view.forward);
  const auto hit = bvh_.nearestHit(ray, frame.view.camera.nearPlane / cosine, frame.view.camera.farPlane / cosine);
  if (!hit) return std::nullopt;
  const WorldTriangle& tri = world_.triangles[hit->triangle];
  const double b0 = 1.0 - hit->b1 - hit->b2;
  VisibleSurface surface;
  surface.point = b0 * tri.p0 + hit->b1 * tri.p1 + hit->b2 * tri.p2;
  surface.normal = glm::normalize(b0 * world_.vertices[tri.vertex[0]].normal +
                                  hit->b1 * world_.vertices[tri.vertex[1]].normal +
                                  hit->b2 * world_.vertices[tri.vertex[2]].normal);
  surface.object = tri.object;
  return surface;
}

ReferenceImages ReferenceRenderer::render(const Frame& frame, const ReferenceOptions& options) const {
  const int width = frame.view.width, height = frame.view.height;
  // `--ideal` traces visibility instead of reading maps (SPEC 3.9).
  const FrameShading shading(frame, world_, bvh_, options,
                             options.ideal ? std::vector<std::unique_ptr<ReferenceShadowMap>>{}
                                           : shadowMaps(frame, options.threads, options.subPixelPrecisionBits));
  const double snap = tol::vertexSnapPx(options.subPixelPrecisionBits);
  const Pipeline& pipeline = frame.scene().pipeline;
  const bool ldr8 = pipeline.path == RenderPath::Deferred && pipeline.deferredBuffer == DeferredBuffer::Ldr8;
  const Vec3 backgroundBound(ldr8 && !options.valueOnly ? tol::kLdr8DecodeAbsError : 0.0);
  const double edgeDistance = tol::edgeDistancePx(options.subPixelPrecisionBits);

  // Pass 1: what each pixel centre sees; pass 2 needs the neighbours' answers
  // to find pixels near a change of surface.
  std::vector<std::optional<RayHit>> hits(std::size_t(width) * height);
  std::vector<SurfaceKey> keys(hits.size());
  forEachRow(height, options.threads, [&](int j) {
    for (int i = 0; i < width; ++i) {
      const std::size_t k = std::size_t(j) * width + i;
      hits[k] = shading.trace(frame.view.rayThroughPixel(i + 0.5, j + 0.5));
      keys[k] = shading.keyOf(hits[k]);
    }
  });

  ReferenceImages out;
  out.value = imaging::Image(width, height, 4);
  out.tolerance = imaging::Image(width, height, 3);
  if (options.keepExactValues) out.exactValue.assign(std::size_t(width) * height, Vec3(0.0));
  if (options.keepToleranceTerms) {
    out.toleranceArithmetic = imaging::Image(width, height, 3);
    out.toleranceShift = imaging::Image(width, height, 3);
  }
  if (options.keepShadowIntervals) out.shadowInterval = imaging::Image(width, height, 3);
  if (options.keepLightPart) out.lightPart = imaging::Image(width, height, 3);
  std::atomic<std::int64_t> evaluations{0}, masked{0}, shadowed{0}, ambiguous{0};

  forEachRow(height, options.threads, [&](int j) {
    std::int64_t rowEvaluations = 0, rowMasked = 0, rowShadowed = 0, rowAmbiguous = 0;
    for (int i = 0; i < width; ++i) {
      const std::size_t k = std::size_t(j) * width + i;
      const double cx = i + 0.5, cy = j + 0.5;
      const SurfaceKey key = keys[k];
      bool compared = true;

      // Near a change of surface? Probe a ring of edgeDistancePx only where a
      // neighbour sees something else; elsewhere no edge can be that close
      // short of a feature thinner than a pixel.
      bool neighbourDiffers = false;
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
          const int ni = i + di, nj = j + dj;
          if (ni < 0 || nj < 0 || ni >= width || nj >= height) continue;
          const std::size_t n = std::size_t(nj) * width + ni;
          if (!(keys[n] == key) ||
              (hits[k] && !shading.sameSurface(hits[k], hits[n], frame.view.rayThroughPixel(ni + 0.5, nj + 0.5))))
            neighbourDiffers = true;
        }
      if (neighbourDiffers) {
        for (int p = 0; p < kEdgeProbes && compared; ++p) {
          const double angle = 2.0 * std::numbers::pi * p / kEdgeProbes;
          const Ray probe = frame.view.rayThroughPixel(cx + edgeDistance * std::cos(angle),
                                                       cy + edgeDistance * std::sin(angle));
          if (!shading.sameSurface(hits[k], shading.trace(probe), probe)) compared = false;
        }
      }

      // The background's value is 0 on every path but ldr8's, whose composite
      // decodes the light buffer's clear value: -log2(1), 0 within log2's
      // absolute error (deferred_buffers.h).
      Vec3 value(0.0), bound(backgroundBound), shiftChange(0.0), interpolation(0.0);
      bool shadowedPixel = false;
      double shadowSpan = 0, shadowLo = 1, shadowHi = 1;
      if (hits[k]) {
        const Ray ray = frame.view.rayThroughPixel(cx, cy);
        if (shading.depthIsAmbiguous(ray, *hits[k]) || shading.nearOpenEdge(*hits[k], cx, cy, edgeDistance))
          compared = false;
        const Shaded centre = shading.shade(*hits[k], !options.valueOnly);
        rowEvaluations += centre.evaluations;
        value = centre.value;
        if (options.keepLightPart)
          for (int c = 0; c < 3; ++c) out.lightPart.at(i, j, c) = float(centre.lights[c]);
        bound = centre.bound;
        interpolation = centre.interpolation;
        shadowedPixel = centre.shadowed;
        shadowSpan = centre.widestShadowSpan;
        shadowLo = centre.widestShadowLo;
        shadowHi = centre.widestShadowHi;
        // Sub-pixel snapping (tolerance_model.h): the larger change of the
        // two shifts along x plus the larger of the two along y, or the
        // largest change at a corner of the square where that is more (a
        // range, cone or shadow edge crossing the square near a corner:
        // the value is not linear there).
        const double shifts[8][2] = {{snap, 0},    {-snap, 0},    {0, snap},     {0, -snap},
                                     {snap, snap}, {-snap, snap}, {snap, -snap}, {-snap, -snap}};
        Vec3 axisChange[2] = {Vec3(0.0), Vec3(0.0)}, cornerChange(0.0);
        for (int a = 0; a < 8; ++a) {
          const Ray shiftedRay = frame.view.rayThroughPixel(cx + shifts[a][0], cy + shifts[a][1]);
          const auto shiftedHit = shading.trace(shiftedRay);
          if (!shading.sameSurface(hits[k], shiftedHit, shiftedRay)) {
            compared = false;
            continue;
          }
          if (options.valueOnly) continue;
          const Shaded shifted = shading.shade(*shiftedHit, false);
          rowEvaluations += shifted.evaluations;
          const Vec3 change = glm::abs(shifted.value - value);
          if (a < 4) axisChange[a / 2] = glm::max(axisChange[a / 2], change);
          else cornerChange = glm::max(cornerChange, change);
          interpolation = glm::max(interpolation, shifted.interpolation);
        }
        shiftChange = glm::max(axisChange[0] + axisChange[1], cornerChange) + centre.shadowEdgeChange;
      }
      const Vec3 tolerance = options.valueOnly ? Vec3(0.0) : tol::pixelTolerance(value, bound, shiftChange, interpolation);
      if (options.keepExactValues) out.exactValue[k] = value;
      if (options.keepToleranceTerms) {
        const Vec3 arithmetic = tol::pixelTolerance(value, bound, Vec3(0.0), interpolation);
        for (int c = 0; c < 3; ++c) {
          out.toleranceArithmetic.at(i, j, c) = float(arithmetic[c]);
          out.toleranceShift.at(i, j, c) = float(shiftChange[c]);
        }
      }
      for (int c = 0; c < 3; ++c) {
        out.value.at(i, j, c) = float(value[c]);
        out.tolerance.at(i, j, c) = float(tolerance[c]);
      }
      out.value.at(i, j, 3) = compared ? 1.0f : 0.0f;
      if (options.keepShadowIntervals) {
        out.shadowInterval.at(i, j, 0) = float(shadowLo);
        out.shadowInterval.at(i, j, 1) = float(shadowHi);
        out.shadowInterval.at(i, j, 2) = shadowedPixel ? 1.0f : 0.0f;
      }
      rowMasked += compared ? 0 : 1;
      if (compared && shadowedPixel) {
        ++rowShadowed;
        if (shadowSpan > tol::kAmbiguousShadowWidth) ++rowAmbiguous;
      }
    }
    evaluations += rowEvaluations;
    masked += rowMasked;
    shadowed += rowShadowed;
    ambiguous += rowAmbiguous;
  });
  out.lightEvaluations = evaluations;
  out.maskedPixels = masked;
  out.shadowedPixels = shadowed;
  out.ambiguousShadowPixels = ambiguous;
  return out;
}

}  // namespace reference
