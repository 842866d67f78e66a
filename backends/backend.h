// The interface every rendering backend implements, and the registry of the
// backends compiled into this build. A backend renders a prepared Frame (the
// lights were chosen on the CPU, lighting/frame.h) and reads back an RGBA float
// image with row 0 at the top; it never decides which lights count.
#pragma once

#include "shaders/shader_variant.h"
#include "imaging/image.h"
#include "lighting/frame.h"

#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace backends {

// The backend names of SPEC 8. A name outside this list is a usage error
// (exit 2); a name in it that this build or machine lacks is a skip (exit 3).
const std::vector<std::string>& specBackendNames();

// The backend, driver or device asked for is not here: a skip (exit 3,
// NotSupported), never a pass.
class NotSupportedError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The driver failed or reported an error (a validation message, a lost
// device, a GL error): exit 4.
class DriverError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct DeviceInfo {
  std::string name;
  std::string driver;
  std::string driverVersion;
  std::string apiVersion;
  std::string selectedBy;  // the options that pick it in `lightcts backends`: "--device 0", "--driver softpipe"
  // The fractional bits of a LINEAR filter's weights the device promises
  // (Vulkan's subTexelPrecisionBits); OpenGL has no query, so 4, the Vulkan
  // minimum SPEC 7 assumes. The tolerance of every filtered lookup uses it.
  int subTexelPrecisionBits = 4;
  // The fractional bits a vertex's framebuffer x and y keep (Vulkan's
  // subPixelPrecisionBits, OpenGL's GL_SUBPIXEL_BITS; at least 4 on both):
  // the sub-pixel term of every tolerance uses it.
  int subPixelPrecisionBits = 4;
};

struct BackendOptions {
  std::string device;  // --device: index or name substring; empty for the default
  // --driver: on the GL backends a Mesa Gallium driver name, "" for llvmpipe
  // (gl/mesa_driver.cpp); on Vulkan a named driver (vulkan/vulkan_drivers.h),
  // "" for whatever the loader finds.
  std::string driver;
  shaders::ShaderVariant variant;
  // Enable the API's validation (VK_LAYER_KHRONOS_validation) and turn any
  // message into a DriverError. On in debug builds and when the environment
  // sets LIGHTCTS_VALIDATION=1 (every ctest run does).
  bool validation = false;
};

// Defaults for BackendOptions::validation: debug build or LIGHTCTS_VALIDATION=1.
bool validationRequestedByDefault();

class Backend {
 public:
  virtual ~Backend() = default;
  virtual DeviceInfo device() const = 0;
  // Builds (or takes from the on-disk cache) the pipeline `frame` needs.
  // draw() does this on demand; benchmarks call it first to time it apart.
  virtual void preparePipeline(const lighting::Frame& frame) = 0;
  // Uploads what `frame`'s prepared scene samples (its baked maps, its
  // lights' cookies) unless that scene's are the ones uploaded last, and
  // points the frame's cookie slots at them. draw() does this on demand;
  // benchmarks call it first to time an upload apart from the draws.
  virtual void prepareTextures(const lighting::Frame& frame) = 0;
  // Draws the frame and waits until the device has finished; no readback.
  virtual void draw(const lighting::Frame& frame) = 0;
  // The last drawn image: RGBA float, row 0 at the top, A = 1 where drawn.
  virtual imaging::Image readback() = 0;
  // The device's own time for the last draw(), in milliseconds, from
  // timestamp queries (Vulkan) or GL_TIME_ELAPSED queries (OpenGL); empty
  // when the device offers none. Benchmarks report it beside wall time.
  virtual std::optional<double> lastDrawDeviceMilliseconds() const { return std::nullopt; }
  // SPEC 3.9's evidence: the shadow maps the last draw() rendered, read back,
  // one single-channel image (the stored depth) per view in the order of
  // lighting::shadowPassViews (the 2D slots, then each cube slot's six
  // faces), row 0 = texel row 0 (mv = 0.5 / N); empty without shadow maps.
  virtual std::vector<imaging::Image> readShadowMaps() = 0;
  // The device's time for the last draw()'s shadow passes alone, in
  // milliseconds (the benchmark times them apart from the lighting; they are
  // part of lastDrawDeviceMilliseconds), when it has timers; empty
  // otherwise or without shadow maps.
  virtual std::optional<double> lastShadowPassDeviceMilliseconds() const { return std::nullopt; }

  imaging::Image render(const lighting::Frame& frame) {
    draw(frame);
    return readback();
  }
};

struct BackendEntry {
  std::string name;
  // Throws NotSupportedError when the API or driver is absent.
  std::function<std::vector<DeviceInfo>(const BackendOptions&)> listDevices;
  // Throws NotSupportedError (no such device or driver) or DriverError.
  std::function<std::unique_ptr<Backend>(const BackendOptions&)> create;
};

// The registry entries of the backends built into this binary (registry.cpp),
// and the one named `name` (SPEC 8 --backend), or null. An entry is how a
// backend is listed and created, not a backend: create() may still find no
// driver or device.
const std::vector<BackendEntry>& builtBackendEntries();
const BackendEntry* findBuiltBackendEntry(const std::string& name);

}  // namespace backends
