#include "lighting/shadow_mask_channels.h"

#include "lighting/light_math.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace lighting {
namespace {

bool isCandidate(const Light& l) {
  return l.mode == LightMode::Mixed && l.shadows && l.shadowStrength > 0;
}

// A directional light overlaps everything; two local lights overlap when their
// range spheres intersect: |p1 - p2| < r1 + r2 (SPEC 5.3).
bool overlaps(const Light& a, const Light& b) {
  if (a.type == LightType::Directional || b.type == LightType::Directional) return true;
  return glm::length(a.position - b.position) < a.range + b.range;
}

// Directional first in scene order, then the others by luminance * range^2
// descending, ties to the lower scene index.
std::vector<int> candidateOrder(const Scene& scene) {
  std::vector<int> directional, other;
  for (int i = 0; i < int(scene.lights.size()); ++i) {
    const Light& l = scene.lights[i];
    if (!isCandidate(l)) continue;
    (l.type == LightType::Directional ? directional : other).push_back(i);
  }
  auto weight = [&](int i) {
    const Light& l = scene.lights[i];
    return luminance(l.finalColor()) * l.range * l.range;
  };
  std::stable_sort(other.begin(), other.end(), [&](int a, int b) { return weight(a) > weight(b); });
  directional.insert(directional.end(), other.begin(), other.end());
  return directional;
}

}  // namespace

ShadowMaskAssignment assignShadowMaskChannels(const Scene& scene) {
  ShadowMaskAssignment result;
  result.channelOfLight.assign(scene.lights.size(), -1);
  result.demotedLight.assign(scene.lights.size(), false);
  std::vector<int> holders;  // lights given a channel so far, in order
  for (int light : candidateOrder(scene)) {
    bool taken[kShadowMaskChannels] = {};
    for (int h : holders)
      if (overlaps(scene.lights[light], scene.lights[h])) taken[result.channelOfLight[h]] = true;
    const auto free = std::find(std::begin(taken), std::end(taken), false);
    ShadowMaskEntry entry{light, -1, false};
    if (free == std::end(taken)) {
      entry.demoted = true;
      result.demotedLight[light] = true;
    } else {
      entry.channel = int(free - std::begin(taken));
      result.channelOfLight[light] = entry.channel;
      holders.push_back(light);
    }
    result.entries.push_back(entry);
  }
  return result;
}

}  // namespace lighting
