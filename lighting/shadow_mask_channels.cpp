#include "lighting/shadow_mask_channels.h"

#include "lighting/light_math.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <climits>
#include <cstdint>
#include <unordered_map>
#include <utility>

namespace lighting {
namespace {

bool isCandidate(const Light& l) {
  return l.mode == LightMode::Mixed && l.shadows && l.shadowStrength > 0;
}

// Two local lights overlap when their range spheres intersect:
// |p1 - p2| < r1 + r2 (SPEC 5.3). A directional light overlaps everything.
bool localLightsOverlap(const Light& a, const Light& b) {
  return glm::length(a.position - b.position) < a.range + b.range;
}

bool overlaps(const Light& a, const Light& b) {
  if (a.type == LightType::Directional || b.type == LightType::Directional) return true;
  return localLightsOverlap(a, b);
}

// Directional first in scene order, then the others by luminance * range^2
// descending, ties to the lower scene index. The keys are computed once
// (not per comparison); sorting (key, index) pairs with the index as the
// second key is the stable sort of SPEC 5.3.
std::vector<int> candidateOrder(const Scene& scene) {
  std::vector<int> order;
  std::vector<std::pair<double, int>> other;  // (-weight, scene index)
  for (int i = 0; i < int(scene.lights.size()); ++i) {
    const Light& l = scene.lights[i];
    if (!isCandidate(l)) continue;
    if (l.type == LightType::Directional) {
      order.push_back(i);
    } else {
      other.emplace_back(luminance(l.finalColor()) * l.range * l.range, i);
    }
  }
  std::stable_sort(other.begin(), other.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  for (const auto& [weight, i] : other) order.push_back(i);
  return order;
}

// Every local candidate, bucketed once by the grid cell of its centre (a
// counting sort: each cell's entries are contiguous), so a light finds the
// earlier holders it may overlap by reading the few cells around it instead
// of testing every holder (the greedy of SPEC 5.3 as written is O(n^2) in the
// number of holders). An entry carries a copy of its light's position and
// range and the channel it holds (-1 until it holds one, and for ever when it
// is demoted), so a query reads contiguous memory rather than a 200-byte
// Light per candidate.
//
// The grid only prunes: every candidate pair is still tested with
// |p1 - p2| < r1 + r2, and a holder h that overlaps light q has its centre
// within r_q + r_h <= r_q + maxRange of q's, so inside the cells of q's box
// padded by maxRange (and by far more than the rounding of glm::length): the
// greedy's answer is unchanged. Lights with a range far above the median
// (more than 4 median diameters), or not finite, stay out of the cells and
// are checked by every query; a query whose box spans more than
// kMaxCellsPerAxis cells reads every entry.
class CandidateGrid {
 public:
  struct Entry {
    Vec3 position;
    double range;
    int channel;  // -1: not (yet) a holder
  };

  CandidateGrid(const Scene& scene, const std::vector<int>& order) : slotOfRank_(order.size(), -1) {
    // The cell: the largest diameter of the lights kept in the grid, where
    // those are the lights up to 4 median diameters across.
    std::vector<double> diameters;
    for (int i : order) {
      const Light& l = scene.lights[i];
      if (l.type != LightType::Directional && std::isfinite(l.range)) diameters.push_back(2 * std::max(l.range, 0.0));
    }
    double limit = 0;
    if (!diameters.empty()) {
      auto middle = diameters.begin() + std::ptrdiff_t(diameters.size() / 2);
      std::nth_element(diameters.begin(), middle, diameters.end());
      limit = 4 * *middle;
    }
    std::vector<int> gridRanks;
    for (std::size_t rank = 0; rank < order.size(); ++rank) {
      const Light& l = scene.lights[order[rank]];
      if (l.type == LightType::Directional) continue;
      const bool inGrid = std::isfinite(l.range) && 2 * std::max(l.range, 0.0) <= limit && finitePosition(l);
      if (inGrid) {
        gridRanks.push_back(int(rank));
        maxRange_ = std::max(maxRange_, std::max(l.range, 0.0));
      } else {
        slotOfRank_[rank] = int(large_.size());
        large_.push_back({l.position, l.range, -1});
      }
    }
    cell_ = maxRange_ > 0 ? 2 * maxRange_ : 1.0;
    if (gridRanks.empty()) return;

    // The box of the centres, in cells; dense offsets when the box has few
    // enough cells, else a hash map from cell to its run of entries.
    std::int64_t lo[3] = {INT64_MAX, INT64_MAX, INT64_MAX}, hi[3] = {INT64_MIN, INT64_MIN, INT64_MIN};
    std::vector<std::array<std::int64_t, 3>> cellOf(gridRanks.size());
    for (std::size_t k = 0; k < gridRanks.size(); ++k) {
      const Vec3& p = scene.lights[order[std::size_t(gridRanks[k])]].position;
      for (int a = 0; a < 3; ++a) {
        cellOf[k][std::size_t(a)] = cellIndex(p[a]);
        lo[a] = std::min(lo[a], cellOf[k][std::size_t(a)]);
        hi[a] = std::max(hi[a], cellOf[k][std::size_t(a)]);
      }
    }
    for (int a = 0; a < 3; ++a) {
      origin_[a] = lo[a];
      extent_[a] = hi[a] - lo[a] + 1;
    }
    const double cellCount = double(extent_[0]) * double(extent_[1]) * double(extent_[2]);
    dense_ = cellCount <= 8.0 * double(gridRanks.size()) + 64;
    std::vector<std::size_t> cellOfEntry(gridRanks.size());
    std::size_t cells = 0;
    if (dense_) {
      cells = std::size_t(cellCount);
      for (std::size_t k = 0; k < gridRanks.size(); ++k) cellOfEntry[k] = denseIndex(cellOf[k]);
    } else {
      sparse_.reserve(gridRanks.size());
      for (std::size_t k = 0; k < gridRanks.size(); ++k) {
        const auto [it, inserted] = sparse_.try_emplace(Key{cellOf[k][0], cellOf[k][1], cellOf[k][2]}, cells);
        if (inserted) ++cells;
        cellOfEntry[k] = it->second;
      }
    }
    start_.assign(cells + 1, 0);
    for (std::size_t c : cellOfEntry) ++start_[c + 1];
    for (std::size_t c = 0; c < cells; ++c) start_[c + 1] += start_[c];
    entries_.resize(gridRanks.size());
    std::vector<std::size_t> next(start_.begin(), start_.end() - 1);
    for (std::size_t k = 0; k < gridRanks.size(); ++k) {
      const std::size_t slot = next[cellOfEntry[k]]++;
      const Light& l = scene.lights[order[std::size_t(gridRanks[k])]];
      entries_[slot] = {l.position, l.range, -1};
      slotOfRank_[std::size_t(gridRanks[k])] = int(slot);
    }
    inGrid_.assign(order.size(), false);
    for (int rank : gridRanks) inGrid_[std::size_t(rank)] = true;
  }

  // The light of candidate rank `rank` now holds `channel`.
  void hold(std::size_t rank, int channel) {
    if (slotOfRank_[rank] < 0) return;  // directional
    (inGrid_.empty() || !inGrid_[rank] ? large_ : entries_)[std::size_t(slotOfRank_[rank])].channel = channel;
  }

  // Calls f(entry) for every holder that may overlap `light`, until f
  // returns false.
  template <typename F>
  void forEachHolderNear(const Light& light, F&& f) const {
    for (const Entry& e : large_)
      if (e.channel >= 0 && !f(e)) return;
    if (entries_.empty()) return;
    std::int64_t lo[3], hi[3];
    if (!queryRange(light, lo, hi)) {
      for (const Entry& e : entries_)
        if (e.channel >= 0 && !f(e)) return;
      return;
    }
    for (std::int64_t x = lo[0]; x <= hi[0]; ++x)
      for (std::int64_t y = lo[1]; y <= hi[1]; ++y)
        for (std::int64_t z = lo[2]; z <= hi[2]; ++z) {
          std::size_t c;
          if (!cellAt({x, y, z}, c)) continue;
          for (std::size_t i = start_[c]; i < start_[c + 1]; ++i)
            if (entries_[i].channel >= 0 && !f(entries_[i])) return;
        }
  }

 private:
  static constexpr std::int64_t kMaxCellsPerAxis = 8;
  static constexpr double kMaxCellIndex = 1e15;

  struct Key {
    std::int64_t x, y, z;
    bool operator==(const Key&) const = default;
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      std::uint64_t h = std::uint64_t(k.x) * 0x9e3779b97f4a7c15ull;
      h ^= std::uint64_t(k.y) * 0xc2b2ae3d27d4eb4full + (h << 6) + (h >> 2);
      h ^= std::uint64_t(k.z) * 0x165667b19e3779f9ull + (h << 6) + (h >> 2);
      return std::size_t(h ^ (h >> 29));
    }
  };

  static bool finitePosition(const Light& l) {
    return std::isfinite(l.position.x) && std::isfinite(l.position.y) && std::isfinite(l.position.z) &&
           std::abs(l.position.x) < 1e300 && std::abs(l.position.y) < 1e300 && std::abs(l.position.z) < 1e300;
  }

  std::int64_t cellIndex(double coordinate) const {
    const double c = std::floor(coordinate / cell_);
    return std::int64_t(std::clamp(c, -kMaxCellIndex, kMaxCellIndex));
  }

  std::size_t denseIndex(const std::array<std::int64_t, 3>& c) const {
    return std::size_t(((c[2] - origin_[2]) * extent_[1] + (c[1] - origin_[1])) * extent_[0] + (c[0] - origin_[0]));
  }

  bool cellAt(const std::array<std::int64_t, 3>& c, std::size_t& index) const {
    if (dense_) {
      for (int a = 0; a < 3; ++a)
        if (c[std::size_t(a)] < origin_[a] || c[std::size_t(a)] >= origin_[a] + extent_[a]) return false;
      index = denseIndex(c);
      return true;
    }
    const auto it = sparse_.find(Key{c[0], c[1], c[2]});
    if (it == sparse_.end()) return false;
    index = it->second;
    return true;
  }

  // The cells holding the centres of every grid light that may overlap:
  // q's box grown by the largest grid range, padded against rounding.
  bool queryRange(const Light& light, std::int64_t lo[3], std::int64_t hi[3]) const {
    const Vec3& p = light.position;
    const double reach = std::max(light.range, 0.0) + maxRange_;
    const double magnitude = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z), reach});
    const double pad = 1e-9 * magnitude + 1e-300;
    for (int a = 0; a < 3; ++a) {
      const double l = std::floor((p[a] - reach - pad) / cell_);
      const double h = std::floor((p[a] + reach + pad) / cell_);
      if (!std::isfinite(l) || !std::isfinite(h) || std::abs(l) >= kMaxCellIndex || std::abs(h) >= kMaxCellIndex)
        return false;
      if (h - l + 1 > double(kMaxCellsPerAxis)) return false;
      lo[a] = std::max(std::int64_t(l), origin_[a]);
      hi[a] = std::min(std::int64_t(h), origin_[a] + extent_[a] - 1);
    }
    return true;
  }

  double cell_ = 1.0;
  double maxRange_ = 0;
  std::int64_t origin_[3] = {0, 0, 0}, extent_[3] = {0, 0, 0};
  bool dense_ = true;
  std::unordered_map<Key, std::size_t, KeyHash> sparse_;
  std::vector<std::size_t> start_;  // entries of cell c: [start_[c], start_[c + 1])
  std::vector<Entry> entries_;
  std::vector<Entry> large_;
  std::vector<int> slotOfRank_;  // per candidate rank: its entry in entries_ or large_, -1 for directional
  std::vector<bool> inGrid_;
};

constexpr unsigned kAllChannels = (1u << kShadowMaskChannels) - 1;

ShadowMaskEntry assign(ShadowMaskAssignment& result, int light, unsigned taken) {
  ShadowMaskEntry entry{light, -1, false};
  if (taken == kAllChannels) {
    entry.demoted = true;
    result.demotedLight[light] = true;
  } else {
    int channel = 0;
    while (taken & (1u << channel)) ++channel;
    entry.channel = channel;
    result.channelOfLight[light] = channel;
  }
  return entry;
}

}  // namespace

bool isBakedLight(const Scene& scene, const ShadowMaskAssignment& assignment, int light) {
  return scene.lights[light].mode == LightMode::Baked || assignment.demotedLight[light];
}

ShadowMaskAssignment assignShadowMaskChannels(const Scene& scene) {
  ShadowMaskAssignment result;
  result.channelOfLight.assign(scene.lights.size(), -1);
  result.demotedLight.assign(scene.lights.size(), false);
  const std::vector<int> order = candidateOrder(scene);
  result.entries.reserve(order.size());
  // Directional lights come first and overlap everything: the channels they
  // hold are taken for every later light.
  unsigned heldByDirectional = 0;
  CandidateGrid grid(scene, order);
  for (std::size_t rank = 0; rank < order.size(); ++rank) {
    const int light = order[rank];
    const Light& l = scene.lights[light];
    unsigned taken = heldByDirectional;
    if (l.type != LightType::Directional) {
      // localLightsOverlap(l, holder), on the holder's copied fields.
      grid.forEachHolderNear(l, [&](const CandidateGrid::Entry& e) {
        if (glm::length(l.position - e.position) < l.range + e.range) taken |= 1u << e.channel;
        return taken != kAllChannels;
      });
    }
    const ShadowMaskEntry entry = assign(result, light, taken);
    result.entries.push_back(entry);
    if (entry.demoted) continue;
    if (l.type == LightType::Directional) {
      heldByDirectional |= 1u << entry.channel;
    } else {
      grid.hold(rank, entry.channel);
    }
  }
  return result;
}

ShadowMaskAssignment assignShadowMaskChannelsBruteForce(const Scene& scene) {
  ShadowMaskAssignment result;
  result.channelOfLight.assign(scene.lights.size(), -1);
  result.demotedLight.assign(scene.lights.size(), false);
  std::vector<int> holders;  // lights given a channel so far, in order
  for (int light : candidateOrder(scene)) {
    unsigned taken = 0;
    for (int h : holders)
      if (overlaps(scene.lights[light], scene.lights[h])) taken |= 1u << result.channelOfLight[h];
    const ShadowMaskEntry entry = assign(result, light, taken);
    result.entries.push_back(entry);
    if (!entry.demoted) holders.push_back(light);
  }
  return result;
}

}  // namespace lighting
