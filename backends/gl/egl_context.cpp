// The EGL context (SPEC 8 `gl-egl`). Without --device: the surfaceless
// platform (EGL_MESA_platform_surfaceless) on Mesa's software driver. With
// --device: the EGL device platform (EGL_EXT_platform_device) and the device
// that the index or name substring picks. No surface either way: the
// renderer draws into its own framebuffer object.
#include "backends/gl/gl_context.h"
#include "backends/gl/shared_library.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <mutex>
#include <optional>
#include <string_view>
#include <vector>

namespace backends::gl {
namespace {

bool hasExtension(const char* extensions, std::string_view name) {
  if (!extensions) return false;
  std::string_view list(extensions);
  for (std::size_t pos = 0; (pos = list.find(name, pos)) != std::string_view::npos; pos += name.size()) {
    const bool startOk = pos == 0 || list[pos - 1] == ' ';
    const std::size_t end = pos + name.size();
    if (startOk && (end == list.size() || list[end] == ' ')) return true;
  }
  return false;
}

// eglGetPlatformDisplayEXT returns one display per platform and device, and
// eglTerminate ends it for every context on it, however often it was
// initialised. So each backend holds a use of its display, and only the last
// use terminates it: a second backend's end must not kill the first one's
// context (backends/tests/two_backends_test.cpp).
class DisplayUse {
 public:
  DisplayUse(EGLDisplay display, PFNEGLTERMINATEPROC terminate) : display_(display), terminate_(terminate) {
    const std::lock_guard lock(mutex());
    ++users()[display_];
  }
  ~DisplayUse() {
    const std::lock_guard lock(mutex());
    if (--users()[display_] == 0) {
      users().erase(display_);
      terminate_(display_);
    }
  }
  DisplayUse(const DisplayUse&) = delete;
  DisplayUse& operator=(const DisplayUse&) = delete;

 private:
  static std::mutex& mutex() {
    static std::mutex m;
    return m;
  }
  static std::map<EGLDisplay, int>& users() {
    static std::map<EGLDisplay, int> u;
    return u;
  }
  EGLDisplay display_;
  PFNEGLTERMINATEPROC terminate_;
};

class EglContext final : public GlContext {
 public:
  explicit EglContext(const BackendOptions& options) : library_({"libEGL.so.1", "libEGL.so"}) {
    getProcAddress_ = library_.require<PFNEGLGETPROCADDRESSPROC>("eglGetProcAddress");
    auto eglInitialize = library_.require<PFNEGLINITIALIZEPROC>("eglInitialize");
    auto eglQueryString = library_.require<PFNEGLQUERYSTRINGPROC>("eglQueryString");
    auto eglBindAPI = library_.require<PFNEGLBINDAPIPROC>("eglBindAPI");
    auto eglChooseConfig = library_.require<PFNEGLCHOOSECONFIGPROC>("eglChooseConfig");
    auto eglCreateContext = library_.require<PFNEGLCREATECONTEXTPROC>("eglCreateContext");
    makeCurrent_ = library_.require<PFNEGLMAKECURRENTPROC>("eglMakeCurrent");
    destroyContext_ = library_.require<PFNEGLDESTROYCONTEXTPROC>("eglDestroyContext");
    terminate_ = library_.require<PFNEGLTERMINATEPROC>("eglTerminate");
    auto eglGetError = library_.require<PFNEGLGETERRORPROC>("eglGetError");

    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    auto getPlatformDisplay =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(getProcAddress_("eglGetPlatformDisplayEXT"));
    if (!getPlatformDisplay) throw NotSupportedError("EGL has no eglGetPlatformDisplayEXT");
    // The Vulkan driver under zink, while the display is initialised
    // (gl_context.h); the rest of the process sees the environment as it was.
    std::unique_ptr<ScopedEnvironment> vulkanDriver;
    if (options.device.empty()) {
      if (!hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless"))
        throw NotSupportedError("EGL has no surfaceless platform (EGL_MESA_platform_surfaceless)");
      vulkanDriver = pinVulkanDriverUnder(requestedMesaDriver(options));
      selectMesaDriver(requestedMesaDriver(options));
      display_ = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    } else {
      if (!options.driver.empty()) {
        vulkanDriver = pinVulkanDriverUnder(options.driver);
        selectMesaDriver(options.driver);
      }
      display_ = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, chooseDevice(options.device), nullptr);
    }
    if (display_ == EGL_NO_DISPLAY) throw NotSupportedError("EGL found no display");
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display_, &major, &minor)) {
      display_ = EGL_NO_DISPLAY;  // nothing to terminate
      throw NotSupportedError("eglInitialize failed (EGL error 0x" + hex(eglGetError()) + ")");
    }
    displayUse_.emplace(display_, terminate_);
    if (!eglBindAPI(EGL_OPENGL_API)) throw NotSupportedError("EGL cannot bind the desktop OpenGL API");

    // No surface is ever made, so no config is needed where EGL allows it.
    EGLConfig config = EGL_NO_CONFIG_KHR;
    if (!hasExtension(eglQueryString(display_, EGL_EXTENSIONS), "EGL_KHR_no_config_context")) {
      const EGLint wanted[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
      EGLint count = 0;
      if (!eglChooseConfig(display_, wanted, &config, 1, &count) || count == 0)
        throw NotSupportedError("EGL has no config for desktop OpenGL");
    }
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, attributes);
    if (context_ == EGL_NO_CONTEXT)
      throw NotSupportedError("EGL cannot create an OpenGL 3.3 core context (EGL error 0x" + hex(eglGetError()) + ")");
    if (!makeCurrent_(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
      throw NotSupportedError("EGL cannot make a context current without a surface (EGL_KHR_surfaceless_context)");
  }

  ~EglContext() override {
    if (display_ == EGL_NO_DISPLAY) return;
    makeCurrent_(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (context_ != EGL_NO_CONTEXT) destroyContext_(display_, context_);
    // displayUse_ terminates the display if this was its last use.
  }

  void makeCurrent() override {
    if (!makeCurrent_(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
      throw DriverError("eglMakeCurrent failed: the EGL context cannot be made current again");
  }

  void* getProcAddress(const char* name) const override {
    return reinterpret_cast<void*>(getProcAddress_(name));
  }

 private:
  static std::string hex(EGLint value) {
    static const char* digits = "0123456789ABCDEF";
    std::string out;
    for (int shift = 12; shift >= 0; shift -= 4) out += digits[(value >> shift) & 0xF];
    return out;
  }

  // The EGL device `selector` names: an index, or a substring of the device's
  // DRM file or "software" for Mesa's software device.
  void* chooseDevice(const std::string& selector) const {
    auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(getProcAddress_("eglQueryDevicesEXT"));
    auto queryString = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(getProcAddress_("eglQueryDeviceStringEXT"));
    if (!queryDevices || !queryString) throw NotSupportedError("EGL has no device platform (EGL_EXT_device_enumeration)");
    EGLint count = 0;
    queryDevices(0, nullptr, &count);
    std::vector<EGLDeviceEXT> devices(std::size_t(std::max(count, 0)));
    queryDevices(count, devices.data(), &count);
    std::vector<std::string> names;
    for (EGLDeviceEXT d : devices) {
      const char* file = hasExtension(queryString(d, EGL_EXTENSIONS), "EGL_EXT_device_drm")
                             ? queryString(d, EGL_DRM_DEVICE_FILE_EXT)
                             : nullptr;
      names.push_back(file ? file : "software");
    }
    const bool isIndex = !selector.empty() && std::all_of(selector.begin(), selector.end(), ::isdigit);
    for (std::size_t i = 0; i < names.size(); ++i)
      if ((isIndex && std::stoul(selector) == i) || (!isIndex && names[i].find(selector) != std::string::npos))
        return devices[i];
    std::string present;
    for (std::size_t i = 0; i < names.size(); ++i) present += " [" + std::to_string(i) + "] " + names[i];
    throw NotSupportedError("no EGL device matches --device '" + selector + "'; present:" + present);
  }

  SharedLibrary library_;
  PFNEGLGETPROCADDRESSPROC getProcAddress_ = nullptr;
  PFNEGLMAKECURRENTPROC makeCurrent_ = nullptr;
  std::optional<DisplayUse> displayUse_;  // after the functions it uses
  PFNEGLDESTROYCONTEXTPROC destroyContext_ = nullptr;
  PFNEGLTERMINATEPROC terminate_ = nullptr;
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<GlContext> createEglContext(const BackendOptions& options) {
  return std::make_unique<EglContext>(options);
}

}  // namespace backends::gl
