// A current OpenGL 3.3 core context, whatever API made it (EGL or OSMesa), and
// the choice of Mesa's software driver made before it is created.
#pragma once

#include "backends/backend.h"
#include "backends/scoped_environment.h"

#include <memory>
#include <string>

namespace backends::gl {

class GlContext {
 public:
  virtual ~GlContext() = default;
  // The address of a GL function in this context, or null.
  virtual void* getProcAddress(const char* name) const = 0;
  // Makes this context current on the calling thread. Every GL call of a
  // backend goes through its own context, also when another backend made
  // (or released) a context since. Throws DriverError when it cannot.
  virtual void makeCurrent() = 0;
};

// Which Mesa driver (GALLIUM_DRIVER) a GL backend is to run on: `--driver`,
// llvmpipe when absent. Set before the context is created, since Mesa reads
// the environment when it loads the driver.
// Any Gallium driver name ([a-z0-9_]+, validMesaDriverName): llvmpipe,
// softpipe and zink go through Mesa's software path (LIBGL_ALWAYS_SOFTWARE),
// any other name is a hardware driver (MESA_LOADER_DRIVER_OVERRIDE).
std::string requestedMesaDriver(const BackendOptions& options);
bool validMesaDriverName(const std::string& driver);
void selectMesaDriver(const std::string& driver);
// The Vulkan driver under a Mesa driver that draws through Vulkan, pinned
// while the GL context is created: for zink, the Vulkan loader's only driver
// is lavapipe's manifest (vulkan::lavapipeDriver()), so gl-egl-zink runs on
// lavapipe and nothing else, whatever other ICDs (a GPU's, SwiftShader) are
// installed; and the loader's implicit device-selection layer is off, since
// with one driver there is nothing to select, and zink's instance, which
// enables the Wayland surface extension, makes it try a Wayland connection
// (libwayland's "XDG_RUNTIME_DIR is invalid or not set" on stderr). Held
// until the display is initialised: zink makes its Vulkan instance then.
// Null for any other driver; NotSupportedError when lavapipe is not installed.
std::unique_ptr<ScopedEnvironment> pinVulkanDriverUnder(const std::string& driver);
// Whether a context whose GL_RENDERER is `renderer` runs on `driver`: the
// name as a whole word, and for a layered driver (zink, virgl, d3d12) its
// own name first, so zink over llvmpipe is not llvmpipe. zink counts only
// over lavapipe, whose device is llvmpipe: "zink (llvmpipe (LLVM 15.0.6,
// 256 bits))" in Mesa 22.3, "zink Vulkan 1.3(llvmpipe ...)" in later ones.
bool rendererRunsOn(const std::string& renderer, const std::string& driver);
// How messages name what `driver` asks for: "zink on lavapipe" for zink.
std::string describeMesaDriver(const std::string& driver);

// EGL: surfaceless platform with Mesa's software driver; with `--device`,
// the EGL device platform and the device that index or name substring picks.
std::unique_ptr<GlContext> createEglContext(const BackendOptions& options);
// OSMesa: off-screen Mesa, always a software driver.
std::unique_ptr<GlContext> createOsmesaContext(const BackendOptions& options);

}  // namespace backends::gl
