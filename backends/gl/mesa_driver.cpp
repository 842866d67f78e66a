#include "backends/gl/gl_context.h"

#include <cstdlib>

namespace backends::gl {

std::string requestedMesaDriver(const BackendOptions& options) {
  return options.driver.empty() ? "llvmpipe" : options.driver;
}

void selectMesaDriver(const std::string& driver) {
  // Mesa's software rasterizers, chosen by name; LIBGL_ALWAYS_SOFTWARE keeps
  // Mesa from picking a hardware driver where one exists.
  ::setenv("GALLIUM_DRIVER", driver.c_str(), 1);
  ::setenv("LIBGL_ALWAYS_SOFTWARE", "1", 1);
}

}  // namespace backends::gl
