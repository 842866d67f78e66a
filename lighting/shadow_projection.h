// SPEC 3.9's shadow-map geometry in double precision, decided once here for
// the reference and both backends: each shadowed light's views (one for a
// directional or spot light, the six cube faces for a point light), the
// projection of a world point into a view's map coordinates (mu, mv) and
// normalised depth, the ray through a texel centre, the receiver offset of
// the lookup, and the matrices the backends upload. The reference builds
// and reads the maps (reference/shadow_maps.h); the GPU copy of the lookup is
// shaders/shadows.glsl.
#pragma once

#include "lighting/camera_view.h"
#include "lighting/scene.h"

#include <glm/mat4x4.hpp>

#include <vector>

namespace lighting {

// Where a point falls in one view. `behind`: at or behind a perspective
// view's apex plane (z_view <= 0), where (mu, mv, depth) mean nothing.
struct MapPoint {
  double mu = 0, mv = 0, depth = 0;
  bool behind = false;
  // SPEC 3.9: outside the map (mu, mv or depth outside [0, 1], or behind the apex) s = 1.
  bool outsideMap() const;
};

// A ray through a texel centre and the part of it the map covers: its depth
// runs from 0 at tMin to 1 at tMax.
struct TexelRay {
  Ray ray;
  double tMin = 0, tMax = 0;
};

// One view: orthographic (directional) or perspective (spot, cube face),
// looking along f with r the mu axis and u the mv axis.
struct ShadowView {
  bool perspective = false;
  Vec3 origin{0.0};      // orthographic: the box's centre; perspective: the light's position
  Vec3 r{0.0}, u{0.0}, f{0.0};
  double halfWidth = 1;  // orthographic: extent; perspective: tan(vertical fov / 2)
  double nearPlane = 0, farPlane = 0;  // perspective: along f; orthographic: -extent and +extent

  MapPoint project(const Vec3& q) const;
  // The view depth z (along f from the origin) to the stored normalised depth.
  double depthOfViewDepth(double z) const;
  // The ray through map coordinates (mu, mv), e.g. a texel centre.
  TexelRay rayThrough(double mu, double mv) const;
  // World to clip (Vulkan's: x, y in [-1, 1] with mu = (x/w + 1)/2 and
  // mv = (y/w + 1)/2, depth z/w in [0, 1]); `cameraPosition` is added to the
  // input first, so the backends' camera-relative positions go in.
  glm::dmat4 clipFromCameraRelative(const Vec3& cameraPosition) const;
};

struct ShadowProjection {
  int light = -1;  // scene light index
  LightType type = LightType::Directional;
  ShadowMapSpec spec;
  std::vector<ShadowView> views;  // 1, or 6 cube faces in the order +X, -X, +Y, -Y, +Z, -Z

  // The view a world point is looked up in: 0, or its cube face (light_space.h).
  int viewOf(const Vec3& q) const;
  // SPEC 3.9's receiver: p' = p + normal_bias N + depth_bias L, with L the
  // unit vector toward the light at p.
  Vec3 offsetReceiver(const Vec3& p, const Vec3& N) const;
  Vec3 towardLight(const Vec3& p) const;
  Vec3 lightPosition{0.0};   // spot, point
  Vec3 lightDirection{0.0};  // the way the light travels
};

// The projection of scene light `light`, which must have a shadow map.
ShadowProjection shadowProjection(const Scene& scene, int light);

// SPEC 3.9's fade at view depth z: saturate((z - 0.8 S) / (0.2 S)), 0 for S = 0.
double shadowFade(double shadowDistance, double viewDepth);
// SPEC 3.9: shadowAtten = saturate(lerp(1, s, strength) + fade).
double shadowAttenuation(double s, double strength, double fade);

// The centre of texel (i, j) of an N x N map: ((i + 0.5)/N, (j + 0.5)/N).
inline double texelCentre(int i, int resolution) { return (i + 0.5) / resolution; }

}  // namespace lighting
