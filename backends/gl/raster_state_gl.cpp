#include "backends/gl/raster_state_gl.h"

namespace backends::gl {

GLenum toGl(lighting::DepthCompare compare) {
  switch (compare) {
    case lighting::DepthCompare::Always: return GL_ALWAYS;
    case lighting::DepthCompare::Less: return GL_LESS;
    case lighting::DepthCompare::LessOrEqual: return GL_LEQUAL;
    case lighting::DepthCompare::GreaterOrEqual: return GL_GEQUAL;
  }
  return GL_LESS;
}

void applyRasterState(const GlFunctions& gl, const lighting::RasterState& raster) {
  gl.glEnable(GL_DEPTH_TEST);
  gl.glDepthFunc(toGl(raster.depthTest));
  gl.glDepthMask(raster.depthWrite ? GL_TRUE : GL_FALSE);
  if (raster.depthClamp)
    gl.glEnable(GL_DEPTH_CLAMP);
  else
    gl.glDisable(GL_DEPTH_CLAMP);
  switch (raster.cull) {
    case lighting::CullMode::None: gl.glDisable(GL_CULL_FACE); break;
    case lighting::CullMode::Front:
      gl.glEnable(GL_CULL_FACE);
      gl.glCullFace(GL_FRONT);
      break;
    case lighting::CullMode::Back:
      gl.glEnable(GL_CULL_FACE);
      gl.glCullFace(GL_BACK);
      break;
  }
  gl.glFrontFace(GL_CCW);
}

void applyOpaqueSurfaceState(const GlFunctions& gl) {
  applyRasterState(gl, lighting::kOpaqueSurfaceState);
  gl.glDisable(GL_BLEND);
}

void applyLightBlend(const GlFunctions& gl, lighting::LightBlend blend) {
  gl.glEnable(GL_BLEND);
  gl.glBlendEquation(GL_FUNC_ADD);
  if (blend == lighting::LightBlend::Multiply)
    gl.glBlendFunc(GL_DST_COLOR, GL_ZERO);  // buffer *= exp2(-c)
  else
    gl.glBlendFunc(GL_ONE, GL_ONE);  // buffer += c
}

}  // namespace backends::gl
