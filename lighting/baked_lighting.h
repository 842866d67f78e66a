// The output of the lightmapper (SPEC 3.6, baking/): per static plane with a
// lightmap, an N x N RGB irradiance map and an N x N four-channel shadow mask.
// Only data and the sampling rule live here, so the reference and every
// backend read the same texels; the baker that fills them is baking/bake.h.
//
// Layout: texel (i, j) of an N x N map is element j * N + i, four floats each.
// i runs along u (local x), j along v (local z), and texel (i, j) has its centre
// at ((i + 0.5) / N, (j + 0.5) / N). Uploaded as is, j is the texture's row,
// so no API flips anything.
#pragma once

#include "lighting/scene.h"

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <memory>
#include <vector>

namespace lighting {

using Vec4 = glm::dvec4;
using Vec2 = glm::dvec2;

struct TexelMap {
  int resolution = 0;          // N; 0: the object has no map
  std::vector<float> texels;   // N * N * 4 floats (RGBA), layout above

  bool empty() const { return resolution == 0; }
  Vec4 texel(int i, int j) const;  // i, j clamped to the edge
};

// A bilinear sample (clamp to edge) and, per channel, the spread (max - min)
// of the four texels it blends: the texture-filtering term of SPEC 7 is a
// fraction of that spread.
struct BilinearSample {
  Vec4 value{0.0};
  Vec4 spread{0.0};
};
BilinearSample sampleBilinear(const TexelMap& map, const Vec2& uv);

// SPEC 3.6: u = x_local / sx + 0.5, v = z_local / sz + 0.5 (planes only).
Vec2 planeLightmapUv(const MeshSpec& plane, const Vec3& localPosition);
// The centre of texel (i, j) of an N x N map, in the plane's local space (y = 0).
Vec3 planeTexelCentreLocal(const MeshSpec& plane, int resolution, int i, int j);

struct ObjectBake {
  TexelMap lightmap;    // rgb: irradiance E of baked and demoted lights; a: 1
  TexelMap shadowMask;  // channel c: visibility of the mixed light holding c; 1 where unused
};

struct BakedLighting {
  std::vector<ObjectBake> objects;  // one per scene object; empty maps where it has none
  std::string cacheKey;             // hex hash of every input of the bake
  double bakeMilliseconds = 0;      // time the bake took when it was computed (also when read from the cache)
  bool fromCache = false;
};

}  // namespace lighting
