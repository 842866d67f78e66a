// The deferred path's programs for OpenGL (SPEC 3.7), made like the forward
// program (program_builder.h), one set per set of constants (the frame's
// features, with LDR8_BUFFER for the ldr8 light buffer; a light program per
// light's texture slots), linked on first use:
//   G-buffer:  forward.vert + gbuffer.frag; blocks and baked-map samplers
//              exactly as the forward program binds them;
//   light:     deferred_light.vert + .frag; FrameBlock (for the
//              view-projection), DeferredLightBlock, DeferredFrameBlock, the
//              G-buffer, the cookies' and shadow maps' blocks and samplers
//              (cookie_textures.h, shadow_maps.h);
//   composite: deferred_composite.vert + .frag; DeferredFrameBlock, the
//              G-buffer and the light buffer.
// Binding points and texture units are shaders/shader_interface.def's: the
// G-buffer textures and the light buffer have units of their own, so no pass
// rebinds another's.
#pragma once

#include "backends/gl/gbuffer_targets.h"
#include "backends/gl/gl_objects.h"
#include "shaders/shader_constants.h"

#include <map>
#include <vector>

namespace backends::gl {

struct DeferredProgramSet {
  GLuint gbuffer = 0;
  std::vector<GLuint> lights;  // one per light pass draw (lighting::lightVolumes order)
  GLuint composite = 0;
};

class DeferredPrograms {
 public:
  explicit DeferredPrograms(const GlFunctions& gl) : gl_(gl) {}
  // The G-buffer and composite programs for the frame's `constants`, and a
  // light program per entry of `lightConstants` (shaders::lightPassConstants);
  // throws DriverError with the compiler's log.
  DeferredProgramSet programs(const shaders::ConstantValues& constants,
                              const std::vector<shaders::ConstantValues>& lightConstants);

 private:
  struct Linked {
    GlName gbuffer, composite;
  };
  Linked build(const shaders::ConstantValues& constants) const;
  GlName buildGbuffer(const shaders::ConstantValues& constants) const;
  GlName buildLight(const shaders::ConstantValues& constants) const;
  GlName buildComposite(const shaders::ConstantValues& constants) const;

  const GlFunctions& gl_;
  std::map<shaders::ConstantValues, Linked> programs_;
  std::map<shaders::ConstantValues, GlName> lights_;
};

}  // namespace backends::gl
