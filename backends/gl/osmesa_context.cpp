// The OSMesa context (SPEC 8 `gl-osmesa`): off-screen Mesa on its software
// driver (GALLIUM_DRIVER, set first). OSMesa needs a colour buffer to make a
// context current; a 1x1 one serves, since the renderer draws into its own
// framebuffer object.
#include "backends/gl/gl_context.h"
#include "backends/gl/shared_library.h"

#include <GL/osmesa.h>

#include <array>

namespace backends::gl {
namespace {

class OsmesaContext final : public GlContext {
 public:
  explicit OsmesaContext(const BackendOptions& options) : library_({"libOSMesa.so.8", "libOSMesa.so"}) {
    if (!options.device.empty())
      throw NotSupportedError("gl-osmesa has one device, Mesa's software driver; --device does not apply");
    auto createContext =
        library_.require<OSMesaContext (*)(const int*, OSMesaContext)>("OSMesaCreateContextAttribs");
    makeCurrent_ = library_.require<GLboolean (*)(OSMesaContext, void*, GLenum, GLsizei, GLsizei)>("OSMesaMakeCurrent");
    destroyContext_ = library_.require<void (*)(OSMesaContext)>("OSMesaDestroyContext");
    getProcAddress_ = library_.require<OSMESAproc (*)(const char*)>("OSMesaGetProcAddress");

    // OSMesa draws through Mesa's software winsys, which only the software
    // rasterizers run on: Mesa 22.3's OSMesa crashes (SIGSEGV) in context
    // creation when GALLIUM_DRIVER names zink, a hardware driver or no driver.
    const std::string driver = requestedMesaDriver(options);
    if (driver != "llvmpipe" && driver != "softpipe")
      throw NotSupportedError("gl-osmesa runs only on Mesa's software rasterizers (llvmpipe, softpipe), not on '" +
                              driver + "'; use gl-egl for it");
    selectMesaDriver(driver);
    const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0, OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
    context_ = createContext(attributes, nullptr);
    if (!context_) throw NotSupportedError("OSMesa cannot create an OpenGL 3.3 core context");
    if (!makeCurrent_(context_, buffer_.data(), GL_UNSIGNED_BYTE, 1, 1))
      throw NotSupportedError("OSMesaMakeCurrent failed");
  }

  ~OsmesaContext() override {
    if (context_) destroyContext_(context_);
  }

  void* getProcAddress(const char* name) const override { return reinterpret_cast<void*>(getProcAddress_(name)); }

  void makeCurrent() override {
    if (!makeCurrent_(context_, buffer_.data(), GL_UNSIGNED_BYTE, 1, 1))
      throw DriverError("OSMesaMakeCurrent failed");
  }

 private:
  SharedLibrary library_;
  GLboolean (*makeCurrent_)(OSMesaContext, void*, GLenum, GLsizei, GLsizei) = nullptr;
  void (*destroyContext_)(OSMesaContext) = nullptr;
  OSMESAproc (*getProcAddress_)(const char*) = nullptr;
  OSMesaContext context_ = nullptr;
  std::array<unsigned char, 4> buffer_{};
};

}  // namespace

std::unique_ptr<GlContext> createOsmesaContext(const BackendOptions& options) {
  return std::make_unique<OsmesaContext>(options);
}

}  // namespace backends::gl
