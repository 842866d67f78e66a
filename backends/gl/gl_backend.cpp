#include "backends/gl/gl_backend.h"

#include "backends/backend_combinations.h"
#include "backends/drawable_features.h"
#include "backends/gl/baked_textures.h"
#include "backends/gl/cluster_lists.h"
#include "backends/gl/cookie_textures.h"
#include "backends/gl/deferred_renderer.h"
#include "backends/gl/forward_programs.h"
#include "backends/gl/gl_context.h"
#include "backends/gl/gl_objects.h"
#include "backends/gl/probe_in_child.h"
#include "backends/gl/raster_state_gl.h"
#include "backends/gl/scene_draws.h"
#include "backends/gl/shadow_maps.h"

#include <chrono>
#include <cstring>
#include <functional>
#include <optional>
#include <vector>

namespace backends::gl {
namespace {

using ContextFactory = std::function<std::unique_ptr<GlContext>(const BackendOptions&)>;

constexpr double kTimerSlackMilliseconds = 0.1;

std::string glString(const GlFunctions& gl, GLenum name) {
  const GLubyte* s = gl.glGetString(name);
  return s ? reinterpret_cast<const char*>(s) : "";
}

// The renderer: an FBO with an RGBA32F colour and a 32-bit float depth
// renderbuffer that every frame ends in, the scene's objects as draws
// (scene_draws.h) with their baked maps (baked_textures.h), drawn forward
// into that FBO, or deferred (deferred_renderer.h) with a composite into it,
// after the frame's shadow-map passes (shadow_maps.h) on either path.
class GlBackend final : public Backend {
 public:
  GlBackend(const ContextFactory& makeContext, const BackendOptions& options)
      : options_(options), context_(makeContext(options)) {
    gl_ = GlFunctions::load([this](const char* name) { return context_->getProcAddress(name); });
    info_.name = glString(gl_, GL_RENDERER);
    info_.driver = glString(gl_, GL_VENDOR);
    info_.driverVersion = glString(gl_, GL_VERSION);
    info_.apiVersion = "GLSL " + glString(gl_, GL_SHADING_LANGUAGE_VERSION);
    // OpenGL 3.3 core: "SUBPIXEL_BITS ... Number of bits of subpixel precision
    // in screen xw and yw", at least 4 (table 6.54).
    GLint subPixelBits = 0;
    gl_.glGetIntegerv(GL_SUBPIXEL_BITS, &subPixelBits);
    info_.subPixelPrecisionBits = int(subPixelBits);
    // Mesa picks its driver once per process; say so rather than run another.
    const std::string wanted = options.device.empty() || !options.driver.empty() ? requestedMesaDriver(options) : "";
    if (!wanted.empty() && !rendererRunsOn(info_.name, wanted))
      throw NotSupportedError("asked for Mesa's " + describeMesaDriver(wanted) + " but the context runs on '" +
                              info_.name + "' (the driver is missing, or another was already loaded in this process)");
    programs_.emplace(gl_);
    bakedTextures_.emplace(gl_);
    cookieTextures_.emplace(gl_);
    shadowMaps_.emplace(gl_, options.variant.mutant, info_.subPixelPrecisionBits);
    // OpenGL's window y runs with NDC y; it has no sub-texel query (DeviceInfo).
    sceneDraws_.emplace(gl_, lighting::DeviceGrid{info_.subPixelPrecisionBits, info_.subTexelPrecisionBits, 1.0f});
    clusterLists_.emplace(gl_);
    deferred_.emplace(gl_, options.variant);
    // GL 3.3 core has timer queries (ARB_timer_query), but a driver may give
    // its counter 0 bits: it then has no clock, and draws are not timed.
    GLint timerBits = 0;
    gl_.glGetQueryiv(GL_TIME_ELAPSED, GL_QUERY_COUNTER_BITS, &timerBits);
    if (timerBits > 0) timer_ = makeQuery(gl_);
    gl_.check("creating the context");
  }

  // The GL objects below are deleted in this backend's context, whichever
  // context another backend made current since.
  ~GlBackend() override {
    try {
      context_->makeCurrent();
    } catch (const std::exception&) {
      // Nothing to delete the names in; the context's own destruction frees them.
    }
  }

  DeviceInfo device() const override { return info_; }

  void preparePipeline(const lighting::Frame& frame) override {
    requireDrawableFeatures(frame);
    context_->makeCurrent();
    const shaders::ConstantValues constants = shaders::constantValues(frame.features, options_.variant);
    if (deferred(frame))
      deferred_->programs(shaders::lightVolumesInBlendOrder(frame, options_.variant), constants);
    else
      programs_->program(constants);
    if (frame.shadows.any()) shadowMaps_->prepareProgram(constants);
  }

  void prepareTextures(const lighting::Frame& frame) override {
    requireDrawableFeatures(frame);
    context_->makeCurrent();
    bakedTextures_->update(*frame.prepared);
    cookieTextures_->update(frame);  // binds the frame's cookie block and slots too
    shadowMaps_->update(frame);      // the maps' textures, the shadow block, the slots' units
  }

  void draw(const lighting::Frame& frame) override {
    requireDrawableFeatures(frame);
    context_->makeCurrent();
    lastDrawMilliseconds_.reset();
    lastShadowMilliseconds_.reset();
    const shaders::ConstantValues constants = shaders::constantValues(frame.features, options_.variant);
    const bool isDeferred = deferred(frame);
    const GLuint forwardProgram = isDeferred ? 0 : programs_->program(constants);
    // The light pass's volumes, each with the slots its program looks up.
    const std::vector<lighting::LightVolume> volumes =
        isDeferred ? shaders::lightVolumesInBlendOrder(frame, options_.variant) : std::vector<lighting::LightVolume>{};
    const DeferredProgramSet deferredPrograms = isDeferred ? deferred_->programs(volumes, constants) : DeferredProgramSet{};
    ensureTarget(frame.scene().image.width, frame.scene().image.height);
    sceneDraws_->update(frame);
    if (!isDeferred) clusterLists_->update(frame);  // the clustered mode's lists, or one zero texel
    prepareTextures(frame);  // before the timed draws: uploads are not drawing
    // SPEC 3.9: the maps are complete before anything that reads them, the
    // forward pass or the deferred light pass; timed apart (GL allows one
    // GL_TIME_ELAPSED query at a time) and added to the draw's time below. The passes leave the framebuffer, viewport and
    // raster state to clearForward and beginFrame, which set all three.
    shadowMaps_->render(frame, constants, *sceneDraws_);
    if (isDeferred)
      deferred_->beginFrame(frame, volumes, width_, height_);  // binds and clears the G-buffer
    else
      clearForward();
    // The query encloses the draws. It begins after the clears on purpose:
    // Mesa binds a newly bound framebuffer to the driver only at the first
    // clear or draw, and llvmpipe bins a GL_TIME_ELAPSED query's start into
    // the framebuffer bound when it begins; begun before the first clear into
    // a new framebuffer, the start lands in the old one, never runs, and the
    // result is the whole CLOCK_MONOTONIC reading (measured: 4.4e6 ms). The
    // deferred path's later framebuffers are cleared or drawn into inside it.
    const auto queryStart = std::chrono::steady_clock::now();
    if (timer_.get()) gl_.glBeginQuery(GL_TIME_ELAPSED, timer_.get());
    if (isDeferred) {
      deferred_->drawFrame(deferredPrograms, *sceneDraws_, *bakedTextures_, framebuffer_.get());
    } else {
      gl_.glUseProgram(forwardProgram);
      sceneDraws_->drawObjects(*bakedTextures_);
    }
    if (timer_.get()) gl_.glEndQuery(GL_TIME_ELAPSED);
    gl_.glFinish();  // draw() returns when the image is complete, as on Vulkan
    const std::string when = "drawing frame " + std::to_string(frame.index) + " of " + frame.scene().sourcePath;
    gl_.check(when.c_str());
    lastShadowMilliseconds_ = shadowMaps_->finishTiming();
    if (timer_.get()) {
      const double hostMilliseconds =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - queryStart).count();
      // After glFinish the result is there: reading it waits for nothing.
      GLuint64 nanoseconds = 0;
      gl_.glGetQueryObjectui64v(timer_.get(), GL_QUERY_RESULT, &nanoseconds);
      gl_.check((when + " (reading its GL_TIME_ELAPSED query)").c_str());
      // The device ran the query's commands after glBeginQuery was called and
      // before glFinish returned; a longer time is a driver's wrong answer,
      // not a time (kTimerSlackMilliseconds: the two clocks' rounding).
      const double milliseconds = double(nanoseconds) * 1e-6;
      // The draw's time includes its shadow passes, as on Vulkan: GL allows
      // one GL_TIME_ELAPSED query at a time, so they had their own.
      if (milliseconds <= hostMilliseconds + kTimerSlackMilliseconds)
        lastDrawMilliseconds_ = milliseconds + lastShadowMilliseconds_.value_or(0.0);
    }
    drawn_ = true;
  }

  std::optional<double> lastDrawDeviceMilliseconds() const override { return lastDrawMilliseconds_; }

  std::vector<imaging::Image> readShadowMaps() override {
    if (!drawn_) throw DriverError("readShadowMaps() before any draw()");
    context_->makeCurrent();
    return shadowMaps_->read();
  }

  std::optional<double> lastShadowPassDeviceMilliseconds() const override { return lastShadowMilliseconds_; }

  // OpenGL's row 0 is the bottom of the image; rows are flipped here so that
  // row 0 is the top (SPEC 1).
  imaging::Image readback() override {
    if (!drawn_) throw DriverError("readback() before any draw()");
    context_->makeCurrent();
    imaging::Image image(width_, height_, 4);
    std::vector<float> rows(image.pixels.size());
    gl_.glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
    gl_.glReadBuffer(GL_COLOR_ATTACHMENT0);
    gl_.glPixelStorei(GL_PACK_ALIGNMENT, 1);
    gl_.glReadPixels(0, 0, width_, height_, GL_RGBA, GL_FLOAT, rows.data());
    gl_.check("reading the image back");
    const std::size_t rowFloats = std::size_t(width_) * 4;
    for (int y = 0; y < height_; ++y)
      std::memcpy(&image.pixels[std::size_t(y) * rowFloats], &rows[std::size_t(height_ - 1 - y) * rowFloats],
                  rowFloats * sizeof(float));
    return image;
  }

 private:
  void ensureTarget(int width, int height) {
    if (framebuffer_.get() && width == width_ && height == height_) return;
    width_ = width;
    height_ = height;
    color_ = makeRenderbuffer(gl_);
    gl_.glBindRenderbuffer(GL_RENDERBUFFER, color_.get());
    gl_.glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA32F, width, height);
    depth_ = makeRenderbuffer(gl_);
    gl_.glBindRenderbuffer(GL_RENDERBUFFER, depth_.get());
    gl_.glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, width, height);
    framebuffer_ = makeFramebuffer(gl_);
    gl_.glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
    gl_.glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_.get());
    gl_.glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.get());
    const GLenum drawBuffer = GL_COLOR_ATTACHMENT0;
    gl_.glDrawBuffers(1, &drawBuffer);
    const GLenum status = gl_.glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
      throw NotSupportedError("the GL driver cannot render to RGBA32F with a 32-bit float depth buffer (status 0x" +
                              std::to_string(status) + ")");
    gl_.check("creating the RGBA32F framebuffer");
  }

  static bool deferred(const lighting::Frame& frame) {
    return frame.scene().pipeline.path == lighting::RenderPath::Deferred;
  }

  // SPEC 1 (raster_state_gl.h); SPIRV-Cross mapped clip z to -1..1. The
  // opaque state comes first: a depth clear honours the depth mask.
  void clearForward() {
    gl_.glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
    gl_.glViewport(0, 0, width_, height_);
    applyOpaqueSurfaceState(gl_);
    // lighting/raster_state.h: the background and the far depth.
    gl_.glClearBufferfv(GL_COLOR, 0, lighting::kBackgroundClear.data());
    gl_.glClearBufferfv(GL_DEPTH, 0, &lighting::kClearDepth);
  }

  BackendOptions options_;
  DeviceInfo info_;
  std::unique_ptr<GlContext> context_;  // first in, last out: GL objects below die while it is current
  GlFunctions gl_;
  std::optional<ForwardPrograms> programs_;
  std::optional<BakedTextures> bakedTextures_;
  std::optional<CookieTextures> cookieTextures_;
  std::optional<ShadowMaps> shadowMaps_;
  std::optional<SceneDraws> sceneDraws_;
  std::optional<ClusterLists> clusterLists_;
  std::optional<DeferredRenderer> deferred_;
  GlName color_, depth_, framebuffer_;
  GlName timer_;  // the GL_TIME_ELAPSED query; none when the driver's timer has 0 bits
  std::optional<double> lastDrawMilliseconds_;
  std::optional<double> lastShadowMilliseconds_;  // the shadow passes' GL_TIME_ELAPSED query
  int width_ = 0, height_ = 0;
  bool drawn_ = false;
};

// `lightcts backends`: each Mesa driver is tried in a child process
// (probe_in_child.h), since Mesa loads one driver per process, and with a
// deadline, since a driver may hang. The drivers tried are those of the
// backend's combinations (backends/backend_combinations.def), or the one
// `--driver` names, which may be any Gallium driver.
std::vector<DeviceInfo> listDrivers(const std::string& backend, const BackendOptions& options) {
  std::vector<std::string> drivers;
  if (!options.driver.empty()) {
    drivers.push_back(options.driver);
  } else {
    for (const BackendCombination& combination : backendCombinations())
      if (combination.backend == backend) drivers.push_back(combination.driver);
  }
  std::vector<DeviceInfo> devices;
  std::string reasons;
  bool allTimedOut = true;
  for (const std::string& driver : drivers) {
    if (!validMesaDriverName(driver)) throw NotSupportedError("'" + driver + "' is not a Mesa driver name");
    const ProbeResult result = probeInChild(backend, driver);
    if (result.device) {
      DeviceInfo info = *result.device;
      info.driver = driver + " (" + info.driver + ")";
      info.selectedBy = "--driver " + driver;
      devices.push_back(info);
    } else {
      allTimedOut = allTimedOut && result.timedOut;
      const std::string reason = drivers.size() == 1 ? result.error : driver + ": " + result.error;
      reasons += (reasons.empty() ? "" : "; ") + reason;
    }
  }
  if (devices.empty() && allTimedOut && !drivers.empty()) throw ProbeTimeoutError(reasons);
  if (devices.empty()) throw NotSupportedError(reasons);
  return devices;
}

BackendEntry entryFor(const std::string& name, ContextFactory makeContext) {
  BackendEntry entry;
  entry.name = name;
  entry.listDevices = [name](const BackendOptions& options) { return listDrivers(name, options); };
  entry.create = [makeContext](const BackendOptions& options) -> std::unique_ptr<Backend> {
    return std::make_unique<GlBackend>(makeContext, options);
  };
  return entry;
}

}  // namespace

BackendEntry eglBackendEntry() { return entryFor("gl-egl", createEglContext); }
BackendEntry osmesaBackendEntry() { return entryFor("gl-osmesa", createOsmesaContext); }

}  // namespace backends::gl
