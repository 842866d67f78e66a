// The load of a deferred frame (SPEC 3.7) for the `lights_per_pixel` counter:
// how many light-pass draws shade a pixel. Every light volume is drawn back
// faces only, depth test GREATER_OR_EQUAL against the G-buffer depth
// (lighting/deferred_lights.h), so a pixel runs a volume's light shader when
// its primary ray leaves the volume at or behind the surface it hits: with the
// surface inside the volume, and also in front of it (where the light adds 0
// but the shader still runs). Full-screen volumes (directional lights) shade
// every pixel with a surface.
#pragma once

#include "lighting/camera_view.h"
#include "lighting/frame.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <vector>

namespace bench {

class DeferredCoverage {
 public:
  explicit DeferredCoverage(const lighting::Frame& frame);
  // `ray` in world space (unit direction), hitting a surface at `hitDistance`.
  int volumesShading(const lighting::Ray& ray, double hitDistance) const;

 private:
  // A closed convex volume as the intersection of its faces' half-spaces:
  // dot(xyz, p) <= w inside (p camera-relative), with its bounding sphere
  // to skip most volumes cheaply.
  struct Volume {
    std::vector<glm::dvec4> planes;
    glm::dvec3 centre{0.0};
    double radius = 0;
  };
  lighting::Vec3 eye_;
  int fullScreen_ = 0;
  std::vector<Volume> volumes_;
};

}  // namespace bench
