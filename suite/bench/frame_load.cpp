#include "suite/bench/frame_load.h"

#include "reference/bvh.h"
#include "reference/world_triangles.h"
#include "suite/bench/deferred_load.h"
#include "lighting/light_clusters.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace bench {

using namespace lighting;

namespace {

// The clustered mode: the directional lights and the lights of the cluster
// the hit point falls in (the shader's loop, LightClusters::clusterAt).
double clusteredLightsAt(const Frame& frame, double pixelX, double pixelY, const Ray& ray, double t) {
  const double depth = glm::dot(ray.origin + t * ray.direction - frame.view.camera.position, frame.view.forward);
  const LightClusters& clusters = *frame.clusters;
  const int cluster = clusters.clusterAt(pixelX, pixelY, depth);
  return double(frame.selection.packed.directional.size()) + double(clusters.count[std::size_t(cluster)]);
}

}  // namespace

FrameLoad loadOf(const Frame& frame) {
  FrameLoad load;
  const int width = frame.view.width, height = frame.view.height;
  load.pixels = double(width) * height;
  load.keptLights = int(frame.selection.packed.directional.size() + frame.selection.packed.other.size());
  const int objects = int(frame.scene().objects.size());
  std::vector<double> perObject(std::size_t(objects), 0.0);
  for (int o = 0; o < objects; ++o) perObject[std::size_t(o)] = double(frame.lightsForObject(o).perPixel.size());
  std::optional<DeferredCoverage> deferred;
  if (frame.scene().pipeline.path == RenderPath::Deferred) deferred.emplace(frame);

  const reference::WorldTriangles world = reference::buildWorldTriangles(*frame.prepared);
  load.triangles = double(world.triangles.size());
  const reference::Bvh bvh(world);
  // At most 256x256 samples: one every `stride` pixels each way.
  const int stride = std::max(1, int(std::ceil(std::sqrt(load.pixels / 65536.0))));
  double sum = 0, samples = 0;
  for (int j = stride / 2; j < height; j += stride) {
    for (int i = stride / 2; i < width; i += stride) {
      const Ray ray = frame.view.rayThroughPixel(i + 0.5, j + 0.5);
      const double cosine = glm::dot(ray.direction, frame.view.forward);
      const auto hit = bvh.nearestHit(ray, frame.view.camera.nearPlane / cosine, frame.view.camera.farPlane / cosine);
      if (hit && deferred) sum += deferred->volumesShading(ray, hit->t);
      else if (hit && frame.clusters) sum += clusteredLightsAt(frame, i + 0.5, j + 0.5, ray, hit->t);
      else if (hit) sum += perObject[std::size_t(world.triangles[std::size_t(hit->triangle)].object)];
      samples += 1;
    }
  }
  load.lightsPerPixel = samples > 0 ? sum / samples : 0;
  return load;
}

}  // namespace bench
