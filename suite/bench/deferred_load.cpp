#include "suite/bench/deferred_load.h"

#include "lighting/deferred_lights.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace bench {

using namespace lighting;

DeferredCoverage::DeferredCoverage(const Frame& frame) : eye_(frame.view.camera.position) {
  for (const LightVolume& light : lightVolumes(frame)) {
    if (light.shape == LightVolumeShape::FullScreen) {
      ++fullScreen_;
      continue;
    }
    Volume volume;
    for (const GpuVec4& v : light.vertices) volume.centre += glm::dvec3(v.x, v.y, v.z);
    volume.centre /= double(std::max<std::size_t>(1, light.vertices.size()));
    for (const GpuVec4& v : light.vertices)
      volume.radius = std::max(volume.radius, glm::length(glm::dvec3(v.x, v.y, v.z) - volume.centre));
    // Three vertices per triangle, counter-clockwise seen from outside: the
    // cross product points out of the volume.
    for (std::size_t i = 0; i + 2 < light.vertices.size(); i += 3) {
      const glm::dvec3 a(light.vertices[i].x, light.vertices[i].y, light.vertices[i].z);
      const glm::dvec3 b(light.vertices[i + 1].x, light.vertices[i + 1].y, light.vertices[i + 1].z);
      const glm::dvec3 c(light.vertices[i + 2].x, light.vertices[i + 2].y, light.vertices[i + 2].z);
      const glm::dvec3 n = glm::cross(b - a, c - a);
      const double length = glm::length(n);
      if (!(length > 0)) continue;  // a degenerate triangle bounds nothing
      volume.planes.emplace_back(n / length, glm::dot(n / length, a));
    }
    volumes_.push_back(std::move(volume));
  }
}

int DeferredCoverage::volumesShading(const Ray& ray, double hitDistance) const {
  const glm::dvec3 origin = ray.origin - eye_, direction = ray.direction;
  int count = fullScreen_;
  for (const Volume& volume : volumes_) {
    // The ray misses the bounding sphere: it misses the volume.
    const glm::dvec3 toCentre = volume.centre - origin;
    const double along = glm::dot(toCentre, direction);
    if (glm::dot(toCentre, toCentre) - along * along > volume.radius * volume.radius) continue;
    // Clip the ray against every face: it is inside on [enter, exit].
    double enter = -std::numeric_limits<double>::infinity(), exit = std::numeric_limits<double>::infinity();
    bool misses = false;
    for (const glm::dvec4& plane : volume.planes) {
      const glm::dvec3 normal(plane);
      const double towards = glm::dot(normal, direction);
      const double room = plane.w - glm::dot(normal, origin);  // >= 0: the origin is inside this face
      if (towards == 0) {
        if (room < 0) misses = true;
      } else if (towards > 0) {
        exit = std::min(exit, room / towards);
      } else {
        enter = std::max(enter, room / towards);
      }
      if (misses || enter > exit) break;
    }
    if (!misses && enter <= exit && exit >= hitDistance) ++count;
  }
  return count;
}

}  // namespace bench
