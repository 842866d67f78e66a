#include "backends/gl/shadow_maps.h"

#include "backends/backend.h"
#include "backends/gl/forward_programs.h"
#include "backends/gl/program_builder.h"
#include "backends/gl/raster_state_gl.h"
#include "lighting/raster_state.h"
#include "shaders/embedded_spirv.h"

#include <cstring>
#include <string>

namespace backends::gl {
namespace {

// As gl_backend.cpp's draw timer: the two clocks' rounding.
constexpr double kTimerSlackMilliseconds = 0.1;

constexpr std::size_t kPassBlockSize = sizeof(lighting::GpuShadowPassBlock);

bool isCubeSlot(int slot) { return slot >= lighting::kMaxShadowMaps; }

}  // namespace


void bindShadowInterface(const GlFunctions& gl, GLuint program) {
  bindUniformBlock(gl, program, shaders::binding::kShadowBlock);
  bindSamplers(gl, program, shaders::binding::kShadowMap);
  bindSamplers(gl, program, shaders::binding::kShadowCube);
}

ShadowMaps::ShadowMaps(const GlFunctions& gl, shaders::Mutant mutant, int subPixelBits)
    : gl_(gl), compareFunc_(GLint(toGl(shaders::shadowLookupCompare(mutant)))), subPixelBits_(subPixelBits) {
  // GL 3.3 promises 48 combined units; shaders/shader_interface.def's are fewer.
  GLint units = 0;
  gl_.glGetIntegerv(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, &units);
  if (units < shaders::binding::kGlTextureUnitCount)
    throw NotSupportedError("the GL driver has " + std::to_string(units) +
                            " texture units (GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS); the shaders use units up to " +
                            std::to_string(shaders::binding::kGlTextureUnitCount - 1));
  gl_.glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize_);
  gl_.glGetIntegerv(GL_MAX_CUBE_MAP_TEXTURE_SIZE, &maxCubeSize_);
  block_ = makeBuffer(gl_);
  passBlocks_ = makeBuffer(gl_);
  passStride_ = uniformBlockStride(gl_, kPassBlockSize);
  // Depth only: no colour buffer to draw into or read from, so the
  // framebuffer is complete with just the depth attachment.
  framebuffer_ = makeFramebuffer(gl_);
  gl_.glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
  const GLenum none = GL_NONE;
  gl_.glDrawBuffers(1, &none);
  gl_.glReadBuffer(GL_NONE);
  gl_.glBindFramebuffer(GL_FRAMEBUFFER, 0);
  // As the backend's draw timer: a counter of 0 bits is no clock.
  GLint timerBits = 0;
  gl_.glGetQueryiv(GL_TIME_ELAPSED, GL_QUERY_COUNTER_BITS, &timerBits);
  if (timerBits > 0) timer_ = makeQuery(gl_);
  gl_.check("creating the shadow maps");
}

void ShadowMaps::update(const lighting::Frame& frame) {
  const lighting::ShadowSlots& slots = frame.shadows;
  usedMaps_ = int(slots.maps.size());
  usedCubes_ = int(slots.cubes.size());
  for (int s = 0; s < usedMaps_; ++s) ensureTexture(frame, maps_[s], slots.maps[s], false);
  for (int s = 0; s < usedCubes_; ++s) ensureTexture(frame, cubes_[s], slots.cubes[s], true);
  // Written for every frame, also without shadows: the full shader reads
  // every slot's kind (None for the unused ones) and the fade.
  const lighting::GpuShadowBlock block = lighting::packShadowBlock(frame);
  gl_.glBindBuffer(GL_UNIFORM_BUFFER, block_.get());
  gl_.glBufferData(GL_UNIFORM_BUFFER, sizeof(block), &block, GL_DYNAMIC_DRAW);
  gl_.glBindBuffer(GL_UNIFORM_BUFFER, 0);
  gl_.glBindBufferRange(GL_UNIFORM_BUFFER, shaders::binding::kShadowBlock.glBinding, block_.get(), 0, sizeof(block));
  bindTextures(false);
  gl_.check("preparing the shadow maps");
}

void ShadowMaps::render(const lighting::Frame& frame, const shaders::ConstantValues& constants,
                        const SceneDraws& scene) {
  views_ = lighting::shadowPassViews(frame);
  timing_ = false;
  if (views_.empty()) return;
  const GLuint program = casterProgram(constants);
  std::vector<unsigned char> blocks(views_.size() * passStride_);
  for (std::size_t v = 0; v < views_.size(); ++v) {
    const lighting::GpuShadowPassBlock block = lighting::packShadowPassBlock(views_[v], subPixelBits_);
    std::memcpy(&blocks[v * passStride_], &block, kPassBlockSize);
  }
  gl_.glBindBuffer(GL_UNIFORM_BUFFER, passBlocks_.get());
  gl_.glBufferData(GL_UNIFORM_BUFFER, GLsizeiptr(blocks.size()), blocks.data(), GL_DYNAMIC_DRAW);
  gl_.glBindBuffer(GL_UNIFORM_BUFFER, 0);

  // The caster samples nothing, so no feedback loop could arise; the maps
  // leave their units anyway while they are render targets.
  bindTextures(true);
  gl_.glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
  // Before the clears: a depth clear honours the depth mask (on here).
  applyRasterState(gl_, lighting::kShadowCasterState);
  gl_.glDisable(GL_BLEND);
  gl_.glUseProgram(program);
  try {
    drawViews(scene);
  } catch (...) {
    // An incomplete framebuffer past the first view: the query must not
    // stay active into the next frame's glBeginQuery.
    if (timing_) gl_.glEndQuery(GL_TIME_ELAPSED);
    timing_ = false;
    views_.clear();
    throw;
  }
  if (timing_) gl_.glEndQuery(GL_TIME_ELAPSED);
  gl_.glUseProgram(0);
  gl_.glBindFramebuffer(GL_FRAMEBUFFER, 0);
  bindTextures(false);
  gl_.check("rendering the shadow maps");
}

void ShadowMaps::drawViews(const SceneDraws& scene) {
  for (std::size_t v = 0; v < views_.size(); ++v) {
    const lighting::ShadowPassView& view = views_[v];
    attach(view);
    // No flip: window row 0 is NDC y = -1, texel row 0, mv near 0, which
    // the lookup's v = mv reads. SPIRV-Cross's clip-z fixup and GL's
    // default depth range [0, 1] store Vulkan's z/w.
    gl_.glViewport(0, 0, view.resolution, view.resolution);
    gl_.glClearBufferfv(GL_DEPTH, 0, &lighting::kClearDepth);  // SPEC 3.9: 1 where no triangle covers a texel
    // The query begins after the first clear, as the backend's draw timer
    // does and for its reason (llvmpipe bins a query's start into the
    // framebuffer the driver has bound, which the first clear binds).
    if (v == 0 && timer_.get()) {
      timingStart_ = std::chrono::steady_clock::now();
      gl_.glBeginQuery(GL_TIME_ELAPSED, timer_.get());
      timing_ = true;
    }
    gl_.glBindBufferRange(GL_UNIFORM_BUFFER, shaders::binding::kShadowPassBlock.glBinding, passBlocks_.get(),
                          GLintptr(v * passStride_), kPassBlockSize);
    scene.drawGeometry();
  }
}

std::optional<double> ShadowMaps::finishTiming() {
  if (!timing_) return std::nullopt;
  timing_ = false;
  const double hostMilliseconds =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - timingStart_).count();
  GLuint64 nanoseconds = 0;
  gl_.glGetQueryObjectui64v(timer_.get(), GL_QUERY_RESULT, &nanoseconds);
  gl_.check("reading the shadow passes' GL_TIME_ELAPSED query");
  // Longer than the host waited is a driver's wrong answer, not a time.
  const double milliseconds = double(nanoseconds) * 1e-6;
  if (milliseconds > hostMilliseconds + kTimerSlackMilliseconds) return std::nullopt;
  return milliseconds;
}

std::vector<imaging::Image> ShadowMaps::read() {
  std::vector<imaging::Image> images;
  if (views_.empty()) return images;
  gl_.glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
  gl_.glPixelStorei(GL_PACK_ALIGNMENT, 1);
  for (const lighting::ShadowPassView& view : views_) {
    const SlotTexture& slot =
        isCubeSlot(view.slot) ? cubes_[view.slot - lighting::kMaxShadowMaps] : maps_[view.slot];
    if (slot.resolution != view.resolution)
      throw DriverError("the shadow maps were remade for another frame after the last draw");
    attach(view);
    // Row j of the read is texel row j (mv = (j + 0.5) / N): kept as is.
    imaging::Image image(view.resolution, view.resolution, 1);
    gl_.glReadPixels(0, 0, view.resolution, view.resolution, GL_DEPTH_COMPONENT, GL_FLOAT, image.pixels.data());
    images.push_back(std::move(image));
  }
  gl_.glBindFramebuffer(GL_FRAMEBUFFER, 0);
  gl_.check("reading the shadow maps back");
  return images;
}

GLuint ShadowMaps::casterProgram(const shaders::ConstantValues& constants) {
  auto found = casters_.find(constants);
  if (found == casters_.end()) {
    GlName program = linkProgram(gl_, shaders::Stage::ShadowCasterVertex, shaders::Stage::ShadowCasterFragment,
                                 constants, "the shadow-caster program");
    bindUniformBlock(gl_, program.get(), shaders::binding::kShadowPassBlock);
    bindUniformBlock(gl_, program.get(), shaders::binding::kObjectBlock);
    gl_.check("linking the shadow-caster program");
    found = casters_.emplace(constants, std::move(program)).first;
  }
  return found->second.get();
}

void ShadowMaps::ensureTexture(const lighting::Frame& frame, SlotTexture& slot,
                               const lighting::ShadowProjection& projection, bool cube) {
  const int n = projection.spec.resolution;
  const GLint limit = cube ? maxCubeSize_ : maxSize_;
  if (n > limit)
    throw NotSupportedError("light '" + frame.scene().lights[projection.light].name + "''s shadow map is " +
                            std::to_string(n) + " x " + std::to_string(n) + " texels; the GL driver's limit is " +
                            std::to_string(limit) +
                            (cube ? " (GL_MAX_CUBE_MAP_TEXTURE_SIZE)" : " (GL_MAX_TEXTURE_SIZE)"));
  const GLenum target = cube ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D;
  gl_.glActiveTexture(GL_TEXTURE0);
  if (!slot.texture.get() || slot.resolution != n) {
    slot.texture = makeTexture(gl_);
    gl_.glBindTexture(target, slot.texture.get());
    // SPEC 3.9: a 32-bit float depth format; the passes fill every texel.
    if (cube) {
      for (int face = 0; face < 6; ++face)
        gl_.glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, GL_DEPTH_COMPONENT32F, n, n, 0,
                         GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
    } else {
      gl_.glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, n, n, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
    }
    slot.resolution = n;
  } else {
    gl_.glBindTexture(target, slot.texture.get());
  }
  // The filter is the slot's light's, which may change while the
  // resolution does not: set every frame. Nearest compares the texel that
  // contains (mu, mv) (`hard`); linear weights the four around it bilinearly
  // (`bilinear`, and each of `tent3x3`'s four fetches).
  const GLint filter = projection.spec.filter == lighting::ShadowFilter::Hard ? GL_NEAREST : GL_LINEAR;
  setSingleLevelSampling(gl_, filter, target, GL_CLAMP_TO_EDGE);
  gl_.glTexParameteri(target, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  gl_.glTexParameteri(target, GL_TEXTURE_COMPARE_FUNC, compareFunc_);
  gl_.glBindTexture(target, 0);
  gl_.check(("making light '" + frame.scene().lights[projection.light].name + "''s shadow map").c_str());
}

void ShadowMaps::bindTextures(bool none) const {
  // Every unit gets its slot's texture or none: a slot the frame does not
  // use is never sampled (its kind in the block is None).
  for (int s = 0; s < lighting::kMaxShadowMaps; ++s) {
    gl_.glActiveTexture(GL_TEXTURE0 + shaders::binding::kShadowMap.glUnit(s));
    gl_.glBindTexture(GL_TEXTURE_2D, !none && s < usedMaps_ ? maps_[s].texture.get() : 0);
  }
  for (int s = 0; s < lighting::kMaxShadowCubes; ++s) {
    gl_.glActiveTexture(GL_TEXTURE0 + shaders::binding::kShadowCube.glUnit(s));
    gl_.glBindTexture(GL_TEXTURE_CUBE_MAP, !none && s < usedCubes_ ? cubes_[s].texture.get() : 0);
  }
  gl_.glActiveTexture(GL_TEXTURE0);
}

// Points the framebuffer's depth attachment at the view's map (a cube
// slot's face); needs the framebuffer bound.
void ShadowMaps::attach(const lighting::ShadowPassView& view) {
  const bool cube = isCubeSlot(view.slot);
  const GLuint texture =
      cube ? cubes_[view.slot - lighting::kMaxShadowMaps].texture.get() : maps_[view.slot].texture.get();
  const GLenum target = cube ? GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + view.face) : GLenum(GL_TEXTURE_2D);
  gl_.glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, target, texture, 0);
  const GLenum status = gl_.glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw NotSupportedError("the GL driver cannot render to a " + std::to_string(view.resolution) + " x " +
                            std::to_string(view.resolution) + " GL_DEPTH_COMPONENT32F " +
                            (cube ? "cube map face" : "texture") + " (framebuffer status " + std::to_string(status) +
                            ")");
}

}  // namespace backends::gl
