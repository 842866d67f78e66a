// The real-time shadow maps of SPEC 3.9 as OpenGL depth textures
// (shaders/shadows.glsl reads them, shaders/shadow_caster.* writes them):
// per 2D slot a GL_DEPTH_COMPONENT32F texture of N x N, per cube slot a cube
// map of six such faces, one level, clamp to edge, each a compare sampler
// (GL_COMPARE_REF_TO_TEXTURE, LEQUAL: lit when depth(p') <= texel) with
// nearest filtering for `hard` and linear for `bilinear` and `tent3x3`.
// Every frame writes the lighting::GpuShadowBlock, renders one depth-only
// pass per lighting::ShadowPassView (every object, no culling, no depth
// bias: lighting::kShadowCasterState) and binds the slots' textures to their
// units, the same units for every program that lights. The depth-only pass's
// ShadowPassBlock is only the shadow-caster program's.
#pragma once

#include "backends/gl/cookie_textures.h"
#include "backends/gl/gl_objects.h"
#include "backends/gl/scene_draws.h"
#include "imaging/image.h"
#include "lighting/frame.h"
#include "lighting/shadow_packing.h"
#include "shaders/shader_constants.h"
#include "shaders/shader_variant.h"

#include <chrono>
#include <map>
#include <optional>
#include <vector>

namespace backends::gl {

// Points `program`'s ShadowBlock and shadow samplers at their binding point
// and units (shaders/shader_interface.def: the 2D slots, then the cube
// slots); needs `program` current. What a specialised program does not use
// is skipped. Every shadow sampler has its own unit, also in a scene without
// shadows: the full shader declares all six, and GL refuses a draw where a
// sampler2DShadow and a samplerCubeShadow (or a cookie's sampler) share one.
void bindShadowInterface(const GlFunctions& gl, GLuint program);

class ShadowMaps {
 public:
  // Throws NotSupportedError when the context has too few texture units for
  // those of shaders/shader_interface.def. Needs the backend's context current.
  // `subPixelBits`: the device's GL_SUBPIXEL_BITS, for the snapping admissible variants.
  ShadowMaps(const GlFunctions& gl, shaders::Mutant mutant, int subPixelBits);

  // Links the shadow-caster program for `constants` unless it is linked
  // (preparePipeline, and render on demand).
  void prepareProgram(const shaders::ConstantValues& constants) { casterProgram(constants); }
  // Makes (or keeps, when the resolution is unchanged) each used slot's
  // texture with the slot's filter, writes the frame's block and binds it
  // and the slots' textures for the draws that follow. NotSupportedError
  // when a map is larger than the driver allows.
  void update(const lighting::Frame& frame);
  // The frame's depth-only passes, every object of `scene` (already updated
  // for the frame) into every view; leaves the draw framebuffer, viewport and
  // raster state to the pass that follows (clearForward, the G-buffer pass
  // set all three). Timed with a GL_TIME_ELAPSED query when the driver's
  // timer has bits.
  void render(const lighting::Frame& frame, const shaders::ConstantValues& constants, const SceneDraws& scene);
  // After the frame's glFinish: the device time of render()'s passes, empty
  // without passes, without a timer, or when the driver's answer is not a time.
  std::optional<double> finishTiming();
  // The depth of every view render() drew last, in its order, row 0 = texel row 0.
  std::vector<imaging::Image> read();

 private:
  struct SlotTexture {
    GlName texture;
    int resolution = 0;
  };

  GLuint casterProgram(const shaders::ConstantValues& constants);
  void ensureTexture(const lighting::Frame& frame, SlotTexture& slot, const lighting::ShadowProjection& projection,
                     bool cube);
  // Binds each used slot's texture to its unit, 0 to the others (and to all
  // with `none`, while the passes render into them).
  void bindTextures(bool none) const;
  void attach(const lighting::ShadowPassView& view);
  // render()'s passes: per view attach, clear to the far depth (lighting::kClearDepth), draw every object.
  void drawViews(const SceneDraws& scene);

  const GlFunctions& gl_;
  const GLint compareFunc_;  // SPEC 3.9, the model's (shaders::shadowLookupCompare)
  const int subPixelBits_;   // GL_SUBPIXEL_BITS, for the snapping admissible variants
  GLint maxSize_ = 0, maxCubeSize_ = 0;
  GlName block_, passBlocks_, framebuffer_, timer_;
  std::size_t passStride_ = 0;
  std::map<shaders::ConstantValues, GlName> casters_;
  SlotTexture maps_[lighting::kMaxShadowMaps];
  SlotTexture cubes_[lighting::kMaxShadowCubes];
  int usedMaps_ = 0, usedCubes_ = 0;
  std::vector<lighting::ShadowPassView> views_;  // what render() drew last
  bool timing_ = false;
  std::chrono::steady_clock::time_point timingStart_;
};

}  // namespace backends::gl
