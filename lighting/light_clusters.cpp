#include "lighting/light_clusters.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

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

// The corners of every cluster: the view-space points where the rays
// through the tile grid's lines (pixel x = i * tileSize, y = j * tileSize,
// clamped to the image) cross the slice boundaries, (tilesX + 1) x
// (tilesY + 1) x (slices + 1) of them, each shared by up to eight clusters.
class ClusterCorners {
 public:
  ClusterCorners(const CameraView& view, const ClusterGrid& grid)
      : across_(grid.tilesX + 1), down_(grid.tilesY + 1), points_(std::size_t(across_) * down_ * (grid.slices + 1)) {
    for (int s = 0; s <= grid.slices; ++s) {
      const double z = grid.sliceStart(s);
      for (int j = 0; j < down_; ++j) {
        const double ndcY = 1.0 - 2.0 * std::min(view.height, j * grid.tileSize) / view.height;
        for (int i = 0; i < across_; ++i) {
          const double ndcX = 2.0 * std::min(view.width, i * grid.tileSize) / view.width - 1.0;
          points_[index(i, j, s)] = viewPointAt(view, ndcX, ndcY, z);
        }
      }
    }
  }
  const Vec3& at(int i, int j, int s) const { return points_[index(i, j, s)]; }

 private:
  std::size_t index(int i, int j, int s) const { return (std::size_t(s) * down_ + j) * across_ + i; }
  int across_, down_;
  std::vector<Vec3> points_;
};

// The padded box around the part of the view frustum that tile (tx, ty)
// and slice s cover: its eight corners (a convex hull, so their box holds
// it), grown by kClusterPadding of its largest coordinate.
ViewBox clusterBox(const ClusterCorners& corners, int tx, int ty, int s) {
  ViewBox box{Vec3(INFINITY), Vec3(-INFINITY)};
  double largest = 0;
  for (int k = 0; k < 8; ++k) {
    const Vec3& p = corners.at(tx + (k & 1), ty + ((k >> 1) & 1), s + (k >> 2));
    box.lo = glm::min(box.lo, p);
    box.hi = glm::max(box.hi, p);
    largest = std::max({largest, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  }
  const Vec3 pad(kClusterPadding * largest);
  box.lo -= pad;
  box.hi += pad;
  return box;
}

// Whether the interval [lo, hi] comes within `radius` of c.
bool withinReach(double c, double radius, double lo, double hi) { return c + radius >= lo && c - radius <= hi; }

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

  const ClusterCorners corners(view, grid);
  std::vector<ViewBox> boxes(std::size_t(grid.clusterCount()));
  for (int s = 0; s < grid.slices; ++s)
    for (int ty = 0; ty < grid.tilesY; ++ty)
      for (int tx = 0; tx < grid.tilesX; ++tx) boxes[grid.clusterIndex(tx, ty, s)] = clusterBox(corners, tx, ty, s);
  // Per slice, the z range of its boxes, and per column (row) of tiles the
  // x (y) range of its boxes: a box lies in the slab of its slice, column and
  // row, so a light that misses one of them misses the box, and the sphere
  // test runs only where all three reach (what makes the binning cost grow
  // with the lights' footprints, not with the cluster count).
  const std::size_t slices = std::size_t(grid.slices);
  std::vector<double> sliceLo(slices, INFINITY), sliceHi(slices, -INFINITY);
  std::vector<double> columnLo(slices * grid.tilesX, INFINITY), columnHi(slices * grid.tilesX, -INFINITY);
  std::vector<double> rowLo(slices * grid.tilesY, INFINITY), rowHi(slices * grid.tilesY, -INFINITY);
  for (int s = 0; s < grid.slices; ++s)
    for (int ty = 0; ty < grid.tilesY; ++ty)
      for (int tx = 0; tx < grid.tilesX; ++tx) {
        const ViewBox& b = boxes[std::size_t(grid.clusterIndex(tx, ty, s))];
        const std::size_t column = std::size_t(s) * grid.tilesX + tx, row = std::size_t(s) * grid.tilesY + ty;
        sliceLo[s] = std::min(sliceLo[s], b.lo.z);
        sliceHi[s] = std::max(sliceHi[s], b.hi.z);
        columnLo[column] = std::min(columnLo[column], b.lo.x);
        columnHi[column] = std::max(columnHi[column], b.hi.x);
        rowLo[row] = std::min(rowLo[row], b.lo.y);
        rowHi[row] = std::max(rowHi[row], b.hi.y);
      }

  // (cluster, light) pairs in packed light order, then a stable counting
  // sort by cluster: each list keeps packed order, with no list per cluster.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  std::vector<int> rows;
  const std::vector<int>& packed = frame.selection.packed.other;
  for (std::size_t k = 0; k < packed.size(); ++k) {
    const Light& light = sceneLights[std::size_t(packed[k])];
    const Vec3 centre = toView(view, light.position);
    const double radius = light.range * (1.0 + kClusterPadding);
    for (int s = 0; s < grid.slices; ++s) {
      if (!withinReach(centre.z, radius, sliceLo[s], sliceHi[s])) continue;
      rows.clear();
      for (int ty = 0; ty < grid.tilesY; ++ty) {
        const std::size_t row = std::size_t(s) * grid.tilesY + ty;
        if (withinReach(centre.y, radius, rowLo[row], rowHi[row])) rows.push_back(ty);
      }
      for (int tx = 0; tx < grid.tilesX; ++tx) {
        const std::size_t column = std::size_t(s) * grid.tilesX + tx;
        if (!withinReach(centre.x, radius, columnLo[column], columnHi[column])) continue;
        for (const int ty : rows) {
          const int c = grid.clusterIndex(tx, ty, s);
          if (sphereTouchesBox(centre, radius, boxes[std::size_t(c)])) pairs.emplace_back(std::uint32_t(c), std::uint32_t(k));
        }
      }
    }
  }
  out.count.assign(boxes.size(), 0);
  for (const auto& [cluster, light] : pairs) ++out.count[cluster];
  out.first.resize(boxes.size());
  std::uint32_t next = 0;
  for (std::size_t c = 0; c < boxes.size(); ++c) {
    out.first[c] = next;
    next += out.count[c];
  }
  out.lights.resize(pairs.size());
  std::vector<std::uint32_t> filled(out.first);
  for (const auto& [cluster, light] : pairs) out.lights[filled[cluster]++] = light;
  return out;
}

std::optional<std::string> clusteredModeRefusal(const Frame& frame) {
  const Pipeline& pipeline = frame.scene().pipeline;
  if (pipeline.profile != Profile::Srp) return "the clustered mode draws the srp profile only; the scene is legacy";
  if (pipeline.path != RenderPath::Forward) return "the clustered mode is a forward path; the scene is deferred";
  if (!frame.objectLists.empty() || frame.features.perObjectLists)
    return "the clustered mode replaces the all-lights loop; the scene uses per-object lists";
  return std::nullopt;
}

void useLightClusters(Frame& frame, const ClusterGridSpec& spec) {
  if (const auto refusal = clusteredModeRefusal(frame)) throw std::invalid_argument("light clusters: " + *refusal);
  frame.clusters = std::make_shared<const LightClusters>(binLights(frame, spec));
  frame.features.clusteredLights = true;
}

}  // namespace lighting
