// The lightmap modes (SPEC 9: baked lightmaps at several resolutions): the
// lightmap scene with its lights baked into an N x N map, drawn like any
// frame, its error taken against the ideal reference of the same lights in
// real time, so the error is what the bake loses (the map's resolution,
// bilinear filtering, and any shadow, which real time does not draw).
#include "baking/bake.h"
#include "suite/bench/bench_families.h"
#include "suite/bench/bench_scenes.h"
#include "suite/bench/fresh_bake.h"
#include "suite/bench/wall_clock.h"

#include <algorithm>
#include <iterator>
#include <vector>

namespace bench {
namespace {

using namespace lighting;

// Bakes `unbaked` fresh (freshBake: no cache, every core) while it is
// cheap: up to 5 bakes (1 with --quick) within about a second (0.2 s); the
// median of their times and the last bake.
std::shared_ptr<const BakedLighting> timedBake(const PreparedScene& unbaked, bool quick, BakeTime& time) {
  const int maxRuns = quick ? 1 : 5;
  const double budgetMs = quick ? 200 : 1000;
  std::vector<double> times;
  std::shared_ptr<const BakedLighting> baked;
  double spentMs = 0;
  do {
    const auto start = Clock::now();
    baked = baking::bakeScene(unbaked, freshBake());
    times.push_back(millisecondsSince(start));
    spentMs += times.back();
  } while (int(times.size()) < maxRuns && spentMs < budgetMs);
  std::sort(times.begin(), times.end());
  const std::size_t n = times.size();
  time.medianMs = n % 2 ? times[n / 2] : 0.5 * (times[n / 2 - 1] + times[n / 2]);
  time.runs = int(n);
  return baked;
}

// `lightmap-N` of `scene`: baked, with bake_ms, compared with `realtime`'s ideal reference.
std::shared_ptr<const BenchFrame> lightmapFrame(bool quick, const LightmapSpec& lightmap, const std::string& scene,
                                                const std::string& mode,
                                                const std::shared_ptr<const PreparedScene>& realtime) {
  const auto unbaked = prepareScene(lightmapScene(lightmap, scene + "-" + mode));
  BenchFrameSpec spec;
  BakeTime bake;
  spec.prepared = baking::withBake(*unbaked, timedBake(*unbaked, quick, bake));
  spec.bake = bake;
  spec.referenceKey = scene + "/realtime";
  spec.errorKey = scene + "/" + mode;
  spec.referencePrepared = realtime;
  return makeBenchFrame(std::move(spec));
}

// One lightmap scene: its `realtime` point and a `lightmap-N` point per N.
void registerLightmapScene(Registrar& r, const LightmapSpec& lightmap, const std::string& scene,
                           const std::vector<int>& resolutions) {
  LightmapSpec realtimeSpec = lightmap;
  realtimeSpec.baked = false;
  // The lights in real time: the `realtime` point, and every lightmap's
  // ideal reference; made when the first of them is.
  const SharedOnDemand<std::shared_ptr<const PreparedScene>> realtime(
      [realtimeSpec, scene] { return prepareScene(lightmapScene(realtimeSpec, scene + "-realtime")); });
  r.frame(scene, "realtime", "", lazyBenchFrame(true, [realtime, scene] {
            BenchFrameSpec spec;
            spec.prepared = realtime.get();
            spec.referenceKey = spec.errorKey = scene + "/realtime";
            return makeBenchFrame(std::move(spec));
          }),
          false);
  const bool quick = r.run().settings.quick;
  for (const int n : resolutions) {
    LightmapSpec baked = lightmap;
    baked.resolution = n;
    const std::string mode = std::string("lightmap-").append(std::to_string(n));
    r.frame(scene, mode, "", lazyBenchFrame(true, [quick, baked, scene, mode, realtime] {
              return lightmapFrame(quick, baked, scene, mode, realtime.get());
            }),
            false);
  }
}

}  // namespace

// `lightmap-WxH`: no shadow, so the error against real time is the map's
// alone and falls with N all the way. `lightmap-shadow-WxH`: the same with
// the shadowed light, at two resolutions: the shadow, which real time does not
// draw, is an error floor that a finer map cannot remove, and the bake casts
// shadow rays. --quick and a slow driver: the first at 320x180, N = 16 and 128.
void registerLightmapModes(Registrar& r) {
  const RunState& run = r.run();
  const bool small = run.slow() || run.settings.quick;
  LightmapSpec spec;
  spec.shadows = false;
  // A slow driver (its frames take seconds) and --quick (a smoke test): a
  // sixteenth of the pixels; the world is the same (the field keeps 16:9).
  if (small) spec.width = 320, spec.height = 180;
  const std::string size = std::to_string(spec.width) + "x" + std::to_string(spec.height);
  std::vector<int> resolutions(std::begin(kLightmapResolutions), std::end(kLightmapResolutions));
  if (small) resolutions = {16, 128};
  registerLightmapScene(r, spec, std::string("lightmap-").append(size), resolutions);
  if (small) return;
  spec.shadows = true;
  registerLightmapScene(r, spec, std::string("lightmap-shadow-").append(size), {64, 512});
}

}  // namespace bench
