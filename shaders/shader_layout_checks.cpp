// The std140 blocks the CPU fills, checked at build time against the layouts
// of the compiled SPIR-V: shader_layout_assertions.h is a static_assert per
// member of every block (offset, type, array length and stride) and per
// block (size), written by shader_layout_checks.cmake from
// `spirv-cross --reflect` and shaders/shader_interface.def. Including the
// headers of every C++ struct the table names is all this file does.
#include "lighting/cookie_packing.h"
#include "lighting/deferred_lights.h"
#include "lighting/gpu_packing.h"
#include "lighting/shadow_packing.h"

#include "shader_layout_assertions.h"  // generated (CMakeLists.txt)
