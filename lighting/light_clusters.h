// Forward+ light binning (URP's clustered forward path): the kept
// point and spot lights of a frame (SPEC 5.1's packed `other` lights, after
// the 64-light selection) binned into screen tiles and view-depth slices by
// their range spheres, so a fragment loops over its cluster's lights only.
// A benchmark mode, never the model's: the conformance scenes test the
// model's own budgets, and this path drops nothing they keep.
//
// Conservative by construction: a light whose range sphere touches any point
// of a cluster is in that cluster's list; a light may sit in a cluster it does
// not touch (the test is sphere against the cluster's view-space bounding
// box, padded), never the reverse. The padding covers what a float32 GPU does
// differently from this double-precision binning: the slice it computes from
// its own view depth, the position and clip position it interpolates, the distance it compares
// with the range (kClusterPadding).
//
// Directional lights shade every pixel and are not binned.
#pragma once

#include "lighting/frame.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace lighting {

// The mode's name everywhere it is chosen: `render --mode`, `compare --mode`
// and the benchmark mode (suite/bench's modeName).
constexpr const char* kClusteredModeName = "clustered";

// The relative padding of every cluster's bounds and every range: 2^-10 of
// the cluster's depth (and of the range), some thousand times float32's
// relative error in a view depth or a distance (2^-24 per operation, a few
// operations). Too much only adds a light to a neighbouring cluster.
constexpr double kClusterPadding = 1.0 / 1024.0;

// What a user of the mode chooses (benchmark parameters).
struct ClusterGridSpec {
  int tileSize = 16;     // pixels per tile side
  int depthSlices = 16;  // slices between the camera's near and far planes
};

// The grid of one frame: tiles of tileSize pixels (the last row and column
// may be partial), slices between near and far: exponential in view depth
// for a perspective camera (each slice's far / near the same ratio, as a
// perspective's depth resolution falls), linear for an orthographic one.
struct ClusterGrid {
  int tileSize = 16;
  int tilesX = 0, tilesY = 0, slices = 0;
  double nearDepth = 0.1, farDepth = 100;
  bool exponential = true;

  int clusterCount() const { return tilesX * tilesY * slices; }
  // Index of cluster (tile x, tile y, slice): x fastest, then y, then slice.
  int clusterIndex(int tileX, int tileY, int slice) const { return (slice * tilesY + tileY) * tilesX + tileX; }
  // The slice a view depth falls in, clamped to [0, slices - 1]: for the
  // exponential grid floor(log(z) * sliceScale() + sliceBias()), for the
  // linear one floor(z * sliceScale() + sliceBias()); the shader evaluates
  // the same expression in float with these two constants.
  int sliceOf(double viewDepth) const;
  double sliceScale() const;
  double sliceBias() const;
  // The view depth where slice s begins (s = slices: the far plane).
  double sliceStart(int slice) const;
};

ClusterGrid clusterGridFor(const CameraView& view, const ClusterGridSpec& spec);

// Per cluster (ClusterGrid::clusterIndex), the range [first, first + count)
// of `lights`, each an index into the frame's packed `other` lights, in
// packed order.
struct LightClusters {
  ClusterGrid grid;
  std::vector<std::uint32_t> first;
  std::vector<std::uint32_t> count;
  std::vector<std::uint32_t> lights;

  std::uint32_t largestCount() const;
  // The cluster of a fragment at pixel coordinates (x right, y down from the
  // image's top-left corner) and view depth, as the shader finds it.
  int clusterAt(double pixelX, double pixelY, double viewDepth) const;
};

// Bins the frame's packed point and spot lights (SPEC 5.1's `other`: an
// srp frame packs no directional light there). Throws std::invalid_argument
// for a tile size or slice count below 1 and for a legacy-profile frame.
LightClusters binLights(const Frame& frame, const ClusterGridSpec& spec);

// Why the clustered mode cannot draw `frame` (the legacy profile, the
// deferred path, per-object lists: each already loops over fewer lights than
// a cluster may hold), or nullopt when it can. Cheap: no binning.
std::optional<std::string> clusteredModeRefusal(const Frame& frame);

// Turns `frame` into its clustered form: bins its lights (binLights), keeps
// the lists in frame.clusters and sets features.clusteredLights, so a backend
// draws each fragment over its cluster's lights; nothing else changes (the
// same kept lights, the same ideal). Throws std::invalid_argument for a frame
// the mode does not draw (clusteredModeRefusal) or a grid below 1.
void useLightClusters(Frame& frame, const ClusterGridSpec& spec);

}  // namespace lighting
