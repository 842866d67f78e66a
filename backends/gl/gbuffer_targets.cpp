#include "backends/gl/gbuffer_targets.h"

#include "backends/backend.h"

#include <string>

namespace backends::gl {
namespace {

struct LightBufferFormat {
  GLenum internalFormat, format, type;
  const char* name;
};

LightBufferFormat lightBufferFormat(lighting::DeferredBuffer buffer) {
  switch (buffer) {
    case lighting::DeferredBuffer::Hdr16: return {GL_RGBA16F, GL_RGBA, GL_FLOAT, "RGBA16F (hdr16)"};
    case lighting::DeferredBuffer::Ldr8: return {GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, "RGBA8 (ldr8)"};
    case lighting::DeferredBuffer::Hdr32: break;
  }
  return {GL_RGBA32F, GL_RGBA, GL_FLOAT, "RGBA32F (hdr32)"};
}

std::string hex(GLenum value) {
  static const char digits[] = "0123456789abcdef";
  std::string out;
  for (int shift = 12; shift >= 0; shift -= 4) out += digits[(value >> shift) & 0xf];
  return "0x" + out;
}

}  // namespace

void GbufferTargets::ensure(int width, int height, lighting::DeferredBuffer buffer) {
  const bool resized = !gbufferFramebuffer_.get() || width != width_ || height != height_;
  if (!resized && buffer == buffer_ && lightFramebuffer_.get()) return;
  width_ = width;
  height_ = height;
  // The light framebuffer holds the depth texture: it goes before a new one
  // replaces it, so no framebuffer keeps a deleted texture attached. Each
  // framebuffer is kept only once complete, so a refused one is retried.
  lightFramebuffer_.reset();
  if (resized) makeGbuffer();
  makeLightBuffer(buffer);
  buffer_ = buffer;
  gl_.glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void GbufferTargets::makeGbuffer() {
  gbufferFramebuffer_.reset();
  for (GlName& colour : colours_) colour = makeTarget(GL_RGBA32F, GL_RGBA, GL_FLOAT);
  depth_ = makeTarget(GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT);
  GlName framebuffer = makeFramebuffer(gl_);
  gl_.glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.get());
  GLenum drawBuffers[kGbufferColourCount];
  for (int i = 0; i < kGbufferColourCount; ++i) {
    drawBuffers[i] = GLenum(GL_COLOR_ATTACHMENT0 + i);
    gl_.glFramebufferTexture2D(GL_FRAMEBUFFER, drawBuffers[i], GL_TEXTURE_2D, colours_[i].get(), 0);
  }
  gl_.glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_.get(), 0);
  // Fragment output location i (gbuffer.frag) writes colour attachment i.
  gl_.glDrawBuffers(kGbufferColourCount, drawBuffers);
  requireComplete("the G-buffer (five RGBA32F colour textures and a 32-bit float depth texture)");
  gl_.check("creating the G-buffer");
  gbufferFramebuffer_ = std::move(framebuffer);
}

void GbufferTargets::makeLightBuffer(lighting::DeferredBuffer buffer) {
  const LightBufferFormat format = lightBufferFormat(buffer);
  lightBuffer_ = makeTarget(format.internalFormat, format.format, format.type);
  GlName framebuffer = makeFramebuffer(gl_);
  gl_.glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.get());
  gl_.glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, lightBuffer_.get(), 0);
  gl_.glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_.get(), 0);
  const GLenum drawBuffer = GL_COLOR_ATTACHMENT0;
  gl_.glDrawBuffers(1, &drawBuffer);
  requireComplete((std::string("the ") + format.name + " light buffer with the G-buffer's depth texture").c_str());
  gl_.check((std::string("creating the ") + format.name + " light buffer").c_str());
  lightFramebuffer_ = std::move(framebuffer);
}

GlName GbufferTargets::makeTarget(GLenum internalFormat, GLenum format, GLenum type) const {
  GlName texture = makeTexture(gl_);
  gl_.glActiveTexture(GL_TEXTURE0);
  gl_.glBindTexture(GL_TEXTURE_2D, texture.get());
  gl_.glTexImage2D(GL_TEXTURE_2D, 0, GLint(internalFormat), width_, height_, 0, format, type, nullptr);
  setSingleLevelSampling(gl_, GL_NEAREST);  // read with texelFetch only
  gl_.glBindTexture(GL_TEXTURE_2D, 0);
  return texture;
}

// GL 3.0 core makes RGBA16F and RGBA32F colour-renderable (with blending);
// a driver that still refuses is a skip with its reason, not a wrong image.
void GbufferTargets::requireComplete(const char* what) const {
  const GLenum status = gl_.glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw NotSupportedError(std::string("the GL driver cannot render to ") + what + " (framebuffer status " +
                            hex(status) + ")");
}

}  // namespace backends::gl
