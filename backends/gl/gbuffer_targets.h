// The deferred path's render targets on OpenGL (SPEC 3.7, docs/model.md):
//   the G-buffer framebuffer: the RGBA32F colour textures of
//   lighting::GbufferTarget (albedo, normal with the window depth in w,
//   base, shadow mask, material) and a
//   GL_DEPTH_COMPONENT32F depth texture;
//   the light framebuffer: the light buffer (RGBA32F hdr32, RGBA16F hdr16,
//   RGBA8 ldr8) and the same depth texture, which the light pass tests
//   against with depth writes off (glDepthMask(GL_FALSE)), never samples.
// Every texture has one level and NEAREST filtering: complete without
// mipmaps, which texelFetch needs (an incomplete texture reads as 0).
#pragma once

#include "backends/gl/gl_objects.h"
#include "lighting/deferred_lights.h"
#include "lighting/scene.h"

#include <array>

namespace backends::gl {

using GbufferTexture = lighting::GbufferTarget;
constexpr int kGbufferColourCount = lighting::kGbufferTargetCount;

class GbufferTargets {
 public:
  explicit GbufferTargets(const GlFunctions& gl) : gl_(gl) {}

  // (Re)makes what a width x height image with `buffer` needs: everything
  // when the size changed, the light buffer alone when only its format did.
  // Throws NotSupportedError when the driver cannot render to a format.
  void ensure(int width, int height, lighting::DeferredBuffer buffer);

  GLuint gbufferFramebuffer() const { return gbufferFramebuffer_.get(); }
  GLuint lightFramebuffer() const { return lightFramebuffer_.get(); }
  GLuint texture(GbufferTexture which) const { return colours_[int(which)].get(); }
  GLuint lightBuffer() const { return lightBuffer_.get(); }

 private:
  void makeGbuffer();
  void makeLightBuffer(lighting::DeferredBuffer buffer);
  GlName makeTarget(GLenum internalFormat, GLenum format, GLenum type) const;
  void requireComplete(const char* what) const;

  const GlFunctions& gl_;
  int width_ = 0, height_ = 0;
  lighting::DeferredBuffer buffer_ = lighting::DeferredBuffer::Hdr32;
  // Declared before the framebuffers, so each framebuffer is deleted before
  // the textures attached to it.
  std::array<GlName, kGbufferColourCount> colours_;
  GlName depth_, lightBuffer_;
  GlName gbufferFramebuffer_, lightFramebuffer_;
};

}  // namespace backends::gl
