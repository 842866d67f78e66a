// The baked maps (SPEC 3.6) as OpenGL textures: per lightmapped object an
// RGBA32F lightmap and shadow mask, one level, LINEAR, clamp to edge, bound
// per draw to the units forward_programs.h gives the samplers. Objects
// without maps get 1x1 stand-ins (lightmap 0, mask 1), as on Vulkan.
#pragma once

#include "backends/gl/gl_objects.h"
#include "lighting/frame.h"

#include <memory>
#include <vector>

namespace backends::gl {

class BakedTextures {
 public:
  // Makes the stand-ins; throws NotSupportedError if the context cannot
  // filter RGBA32F textures. Needs the backend's context current.
  explicit BakedTextures(const GlFunctions& gl);

  // Uploads the maps of `scene` unless its bake is the one uploaded last (a
  // CPU mutant hands in a different bake; a new bake means new textures).
  void update(const lighting::PreparedScene& scene);
  // Binds object `object`'s lightmap and shadow mask to their texture units.
  void bind(int object) const;

 private:
  struct ObjectTextures {
    GlName lightmap;    // 0: the object has no lightmap; the stand-in is bound
    GlName shadowMask;  // 0: likewise
  };

  GlName upload(const lighting::TexelMap& map, const char* what) const;

  const GlFunctions& gl_;
  GLint maxSize_ = 0;
  GlName noLightmap_, noShadowMask_;
  // Held, not just compared: while this pointer lives no other bake can get
  // its address, so "same pointer" really means "same bake".
  std::shared_ptr<const lighting::BakedLighting> uploaded_;
  std::vector<ObjectTextures> objects_;
};

}  // namespace backends::gl
