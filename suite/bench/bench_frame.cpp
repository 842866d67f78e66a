#include "suite/bench/bench_frame.h"

#include "lighting/visible_lights.h"

#include <algorithm>
#include <cstdio>

namespace bench {
namespace {

using namespace lighting;

// SPEC 5.1: srp keeps up to kSrpMaxOtherLights point/spot lights, legacy
// kLegacyMaxLights; a scene with every light in view must keep min(lights, budget).
void checkKept(const Frame& frame) {
  const Scene& scene = frame.scene();
  const int budget = scene.pipeline.profile == Profile::Legacy ? kLegacyMaxLights : kSrpMaxOtherLights;
  const std::size_t expected = std::min<std::size_t>(scene.lights.size(), std::size_t(budget));
  const std::size_t kept = frame.selection.packed.other.size();
  if (kept != expected)
    std::fprintf(stderr, "render_bench: synthetic scene %s keeps %zu point/spot lights, not %zu\n",
                 scene.name.c_str(), kept, expected);
}

// The dense field's promise (kDenseFieldLeastObjectLights): every object's
// list (SPEC 5.2, before the cut to 8) holds at least `least` lights.
void checkObjectLights(const Frame& frame, int least) {
  for (std::size_t o = 0; o < frame.objectLists.size(); ++o)
    if (frame.objectLists[o].count < least)
      std::fprintf(stderr, "render_bench: synthetic scene %s: object %zu is touched by %d lights, not %d or more\n",
                   frame.scene().name.c_str(), o, frame.objectLists[o].count, least);
}

}  // namespace

std::shared_ptr<const BenchFrame> makeBenchFrame(BenchFrameSpec spec) {
  auto bench = std::make_shared<BenchFrame>();
  bench->frame = prepareFrame(spec.prepared, 0);
  if (spec.clusters) useLightClusters(bench->frame, *spec.clusters);
  bench->load = loadOf(bench->frame);
  if (spec.everyLightInView) checkKept(bench->frame);
  if (spec.leastObjectLights > 0) checkObjectLights(bench->frame, spec.leastObjectLights);
  bench->spec = std::move(spec);
  return bench;
}

}  // namespace bench
