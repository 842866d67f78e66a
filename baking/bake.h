// The lightmapper of SPEC 3.6 and 5.3: for every static plane with
// lightmap_resolution > 0, an irradiance map of the baked lights (mode baked,
// and mixed lights demoted in 5.3) with their falloff and ray-cast shadows,
// and a shadow mask holding each channel's mixed light's visibility. Rays use
// the reference's BVH (reference/bvh.h) over every triangle of the scene.
//
// Deterministic (each texel is computed alone, in double, then rounded to
// float once), parallel over rows, and cached on disk keyed by a hash of every
// input, so a test run bakes each scene once.
#pragma once

#include "lighting/baked_lighting.h"
#include "lighting/frame.h"

#include <cstdint>
#include <memory>
#include <string>

namespace baking {

// Part of every cache key: bump it whenever a change to the baker changes a
// texel, so bakes cached by an older baker are never read again.
constexpr std::uint32_t kBakerVersion = 1;

struct BakeOptions {
  int threads = 0;  // 0: every core
  // Where bakes are cached: this folder; empty: the bakes/ folder of the
  // cache folder the Vulkan pipeline cache uses ($LIGHTCTS_CACHE_DIR, else
  // $XDG_CACHE_HOME/lightcts, else ~/.cache/lightcts).
  std::string cacheDirectory;
  bool useCache = true;
  // Test only (mutant legacy-falloff-baked): lights whose bake_falloff is
  // inverse_squared are baked with the legacy falloff. Part of the cache key.
  bool mutantLegacyFalloff = false;
};

// The maps of every lightmapped object of `prepared` (empty maps elsewhere).
std::shared_ptr<const lighting::BakedLighting> bakeScene(const lighting::PreparedScene& prepared,
                                                          const BakeOptions& options = {});

// lighting::prepareScene plus, when some object has a lightmap, its bake.
// Every command, worker and test that renders a scene prepares it here.
std::shared_ptr<const lighting::PreparedScene> prepareBakedScene(lighting::Scene scene,
                                                                  const BakeOptions& options = {});

// A copy of `prepared` with its maps replaced by `baked`.
std::shared_ptr<const lighting::PreparedScene> withBake(const lighting::PreparedScene& prepared,
                                                         std::shared_ptr<const lighting::BakedLighting> baked);

}  // namespace baking
