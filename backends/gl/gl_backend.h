// The OpenGL backends (SPEC 8 `gl-egl` and `gl-osmesa`): one renderer
// (gl_backend.cpp) behind two ways of making a context (egl_context.cpp,
// osmesa_context.cpp), on Mesa's llvmpipe or softpipe (`--driver`).
#pragma once

#include "backends/backend.h"

namespace backends::gl {

BackendEntry eglBackendEntry();
BackendEntry osmesaBackendEntry();

}  // namespace backends::gl
