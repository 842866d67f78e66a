#include "lighting/light_clusters.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace lighting {
namespace {

// A cluster's bounds in view coordinates: x along the camera's right, y
// along up, z the view depth, all relative to the camera position.
struct ViewBox {
  Vec3 lo{0}, hi{0};
};

Vec3 toView(const CameraView& view, const Vec3& world) {
  const Vec3 d = world - view.camera.position;
  return {glm::dot(d, view.right), glm::dot(d, view.up), glm::dot(d, view.forward)};
}

// The point of the ray through NDC (x, y) at view depth z, in view coordinates.
Vec3 viewPointAt(const CameraView& view, double ndcX, double ndcY, double z) {
  const Ray ray = view.rayThroughNdc(ndcX, ndcY);
  const double t = (z - view.viewDepth(ray.origin)) / glm::dot(ray.direction, view.forward);
  return toView(view, ray.origin + t * ray.direction);
}

// The padded box around the part of the view frustum that tile (tx, ty)
// and slice s cover: the eight corners of that frustum piece (a convex
// hull, so its box holds it), grown by kClusterPadding of its largest
// coordinate.
ViewBox clusterBox(const CameraView& view, const ClusterGrid& grid, int tx, int ty, int s) {
  const int x0 = tx * grid.tileSize, x1 = std::min(view.width, x0 + grid.tileSize);
  const int y0 = ty * grid.tileSize, y1 = std::min(view.height, y0 + grid.tileSize);
  const std::array<double, 2> ndcX = {2.0 * x0 / view.width - 1.0, 2.0 * x1 / view.width - 1.0};
  const std::array<double, 2> ndcY = {1.0 - 2.0 * y0 / view.height, 1.0 - 2.0 * y1 / view.height};
  const std::array<double, 2> depth = {grid.sliceStart(s), grid.sliceStart(s + 1)};
  ViewBox box{Vec3(INFINITY), Vec3(-INFINITY)};
  double largest = 0;
  for (const double x : ndcX)
    for (const double y : ndcY)
      for (const double z : depth) {
        const Vec3 p = viewPointAt(view, x, y, z);
        box.lo = glm::min(box.lo, p);
        box.hi = glm::max(box.hi, p);
        largest = std::max({largest, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
      }
  const Vec3 pad(kClusterPadding * largest);
  box.lo -= pad;
  box.hi += pad;
  return box;
}

// Whether a sphere and a box share a point: the squared distance from the
// centre to the box's nearest point against r^2.
bool sphereTouchesBox(const Vec3& centre, double radius, const ViewBox& box) {
  const Vec3 nearest = glm::clamp(centre, box.lo, box.hi);
  const Vec3 d = centre - nearest;
  return glm::dot(d, d) <= radius * radius;
}

}  // namespace

int ClusterGrid::sliceOf(double viewDepth) const {
  const double x = exponential ? std::log(std::max(viewDepth, nearDepth)) : viewDepth;
  const double s = std::floor(x * sliceScale() + sliceBias());
  return int(std::clamp(s, 0.0, double(slices - 1)));
}

double ClusterGrid::sliceScale() const {
  return exponential ? slices / std::log(farDepth / nearDepth) : slices / (farDepth - nearDepth);
}

double ClusterGrid::sliceBias() const {
  return exponential ? -std::log(nearDepth) * sliceScale() : -nearDepth * sliceScale();
}

double ClusterGrid::sliceStart(int slice) const {
  const double f = double(slice) / slices;
  return exponential ? nearDepth * std::pow(farDepth / nearDepth, f) : nearDepth + (farDepth - nearDepth) * f;
}

ClusterGrid clusterGridFor(const CameraView& view, const ClusterGridSpec& spec) {
  if (spec.tileSize < 1 || spec.depthSlices < 1)
    throw std::invalid_argument("light clusters: the tile size and the slice count must be at least 1");
  ClusterGrid grid;
  grid.tileSize = spec.tileSize;
  grid.tilesX = (view.width + spec.tileSize - 1) / spec.tileSize;
  grid.tilesY = (view.height + spec.tileSize - 1) / spec.tileSize;
  grid.slices = spec.depthSlices;
  grid.nearDepth = view.camera.nearPlane;
  grid.farDepth = view.camera.farPlane;
  grid.exponential = view.camera.projection == Projection::Perspective;
  return grid;
}

std::uint32_t LightClusters::largestCount() const {
  return count.empty() ? 0 : *std::max_element(count.begin(), count.end());
}

int LightClusters::clusterAt(double pixelX, double pixelY, double viewDepth) const {
  const int tx = std::clamp(int(std::floor(pixelX / grid.tileSize)), 0, grid.tilesX - 1);
  const int ty = std::clamp(int(std::floor(pixelY / grid.tileSize)), 0, grid.tilesY - 1);
  return grid.clusterIndex(tx, ty, grid.sliceOf(viewDepth));
}

LightClusters binLights(const Frame& frame, const ClusterGridSpec& spec) {
  // The legacy profile packs directional lights among the others and has
  // its own 16-light budget: not this mode's.
  if (frame.prepared->scene.pipeline.profile != Profile::Srp)
    throw std::invalid_argument("light clusters: the clustered mode draws the srp profile only");
  const CameraView& view = frame.view;
  const std::vector<Light>& sceneLights = frame.prepared->scene.lights;
  LightClusters out;
  out.grid = clusterGridFor(view, spec);
  const ClusterGrid& grid = out.grid;

  std::vector<ViewBox> boxes(std::size_t(grid.clusterCount()));
  for (int s = 0; s < grid.slices; ++s)
    for (int ty = 0; ty < grid.tilesY; ++ty)
      for (int tx = 0; tx < grid.tilesX; ++tx) boxes[grid.clusterIndex(tx, ty, s)] = clusterBox(view, grid, tx, ty, s);
  // The z range of each slice's boxes (the same for every tile of a
  // perspective slice up to padding): a light outside it skips the slice.
  std::vector<double> sliceLo(grid.slices, INFINITY), sliceHi(grid.slices, -INFINITY);
  for (int s = 0; s < grid.slices; ++s)
    for (int t = 0; t < grid.tilesX * grid.tilesY; ++t) {
      const ViewBox& b = boxes[std::size_t(s) * grid.tilesX * grid.tilesY + t];
      sliceLo[s] = std::min(sliceLo[s], b.lo.z);
      sliceHi[s] = std::max(sliceHi[s], b.hi.z);
    }

  std::vector<std::vector<std::uint32_t>> perCluster(boxes.size());
  const std::vector<int>& packed = frame.selection.packed.other;
  for (std::size_t k = 0; k < packed.size(); ++k) {
    const Light& light = sceneLights[std::size_t(packed[k])];
    const Vec3 centre = toView(view, light.position);
    const double radius = light.range * (1.0 + kClusterPadding);
    for (int s = 0; s < grid.slices; ++s) {
      if (centre.z + radius < sliceLo[s] || centre.z - radius > sliceHi[s]) continue;
      for (int ty = 0; ty < grid.tilesY; ++ty)
        for (int tx = 0; tx < grid.tilesX; ++tx) {
          const int c = grid.clusterIndex(tx, ty, s);
          if (sphereTouchesBox(centre, radius, boxes[std::size_t(c)])) perCluster[std::size_t(c)].push_back(std::uint32_t(k));
        }
    }
  }
  out.first.reserve(perCluster.size());
  out.count.reserve(perCluster.size());
  for (const std::vector<std::uint32_t>& list : perCluster) {
    out.first.push_back(std::uint32_t(out.lights.size()));
    out.count.push_back(std::uint32_t(list.size()));
    out.lights.insert(out.lights.end(), list.begin(), list.end());
  }
  return out;
}

void useLightClusters(Frame& frame, const ClusterGridSpec& spec) {
  const Pipeline& pipeline = frame.scene().pipeline;
  if (pipeline.profile != Profile::Srp)
    throw std::invalid_argument("light clusters: the clustered mode draws the srp profile only; the scene is legacy");
  if (pipeline.path != RenderPath::Forward)
    throw std::invalid_argument("light clusters: the clustered mode is a forward path; the scene is deferred");
  if (!frame.objectLists.empty() || frame.features.perObjectLists)
    throw std::invalid_argument("light clusters: the clustered mode replaces the all-lights loop; the scene uses "
                                "per-object lists");
  frame.clusters = std::make_shared<const LightClusters>(binLights(frame, spec));
  frame.features.clusteredLights = true;
}

}  // namespace lighting
