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

}  // namespace

std::shared_ptr<const BenchFrame> makeBenchFrame(BenchFrameSpec spec) {
  auto bench = std::make_shared<BenchFrame>();
  bench->frame = prepareFrame(spec.prepared, 0);
  bench->load = loadOf(bench->frame);
  if (spec.everyLightInView) checkKept(bench->frame);
  bench->spec = std::move(spec);
  return bench;
}

}  // namespace bench
