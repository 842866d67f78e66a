#include "backends/gl/cookie_textures.h"

#include "backends/backend.h"
#include "backends/cookie_texels.h"
#include "backends/gl/program_builder.h"
#include "lighting/cookie_packing.h"

#include <chrono>
#include <string>

namespace backends::gl {

void bindCookieInterface(const GlFunctions& gl, GLuint program) {
  bindUniformBlock(gl, program, shaders::binding::kCookieBlock);
  bindSamplers(gl, program, shaders::binding::kCookieTexture);
  bindSamplers(gl, program, shaders::binding::kCookieCube);
}

CookieTextures::CookieTextures(const GlFunctions& gl) : gl_(gl) {
  // SPEC 3.10: point cookies are seamless across faces (core since GL 3.2).
  gl_.glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
  gl_.glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize_);
  gl_.glGetIntegerv(GL_MAX_CUBE_MAP_TEXTURE_SIZE, &maxCubeSize_);
  block_ = makeBuffer(gl_);
  gl_.check("creating the cookie block");
}

void CookieTextures::update(const lighting::Frame& frame) {
  if (frame.prepared != scene_) upload(frame.prepared);
  const lighting::GpuCookieBlock block = lighting::packCookieBlock(frame);
  gl_.glBindBuffer(GL_UNIFORM_BUFFER, block_.get());
  gl_.glBufferData(GL_UNIFORM_BUFFER, sizeof(block), &block, GL_DYNAMIC_DRAW);
  gl_.glBindBuffer(GL_UNIFORM_BUFFER, 0);
  gl_.glBindBufferRange(GL_UNIFORM_BUFFER, shaders::binding::kCookieBlock.glBinding, block_.get(), 0, sizeof(block));
  // Every unit gets its slot's texture or none: a slot the frame does not
  // use is never sampled (its lights carry slot -1).
  const lighting::CookieSlots& slots = frame.cookies;
  for (int s = 0; s < lighting::kMaxCookieTextures; ++s) {
    gl_.glActiveTexture(GL_TEXTURE0 + shaders::binding::kCookieTexture.glUnit(s));
    const bool used = s < int(slots.textureLights.size());
    gl_.glBindTexture(GL_TEXTURE_2D, used ? textures_[slots.textureLights[s]].get() : 0);
  }
  for (int s = 0; s < lighting::kMaxCookieCubes; ++s) {
    gl_.glActiveTexture(GL_TEXTURE0 + shaders::binding::kCookieCube.glUnit(s));
    const bool used = s < int(slots.cubeLights.size());
    gl_.glBindTexture(GL_TEXTURE_CUBE_MAP, used ? textures_[slots.cubeLights[s]].get() : 0);
  }
  gl_.glActiveTexture(GL_TEXTURE0);
  gl_.check("binding the cookies");
}

void CookieTextures::upload(const std::shared_ptr<const lighting::PreparedScene>& prepared) {
  const std::vector<lighting::Light>& lights = prepared->scene.lights;
  std::vector<GlName> textures(lights.size());
  const auto start = std::chrono::steady_clock::now();
  bool any = false;
  for (std::size_t l = 0; l < lights.size(); ++l) {
    if (!lights[l].cookie) continue;
    any = true;
    const lighting::Cookie& cookie = *lights[l].cookie;
    const CookieAddressing addressing = cookieAddressing(lights[l]);
    const bool cube = addressing == CookieAddressing::Cube;
    const int w = cookieWidth(cookie), h = cookieHeight(cookie);
    const GLint limit = cube ? maxCubeSize_ : maxSize_;
    if (w > limit || h > limit)
      throw NotSupportedError("light '" + lights[l].name + "''s cookie is " + std::to_string(w) + " x " +
                              std::to_string(h) + " texels; the GL driver's limit is " + std::to_string(limit) +
                              (cube ? " (GL_MAX_CUBE_MAP_TEXTURE_SIZE)" : " (GL_MAX_TEXTURE_SIZE)"));
    const std::vector<float> texels = cookieTexels(cookie);
    textures[l] = makeTexture(gl_);
    const GLenum target = cube ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D;
    gl_.glActiveTexture(GL_TEXTURE0);
    gl_.glBindTexture(target, textures[l].get());
    gl_.glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    // Row j of the image is GL's row j, which t = (j + 0.5) / h addresses:
    // image row 0 is v = 0 (SPEC 3.10), nothing is flipped.
    const std::size_t faceFloats = std::size_t(w) * std::size_t(h);
    if (cube) {
      for (int face = 0; face < 6; ++face)
        gl_.glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, GL_R32F, w, h, 0, GL_RED, GL_FLOAT,
                         texels.data() + face * faceFloats);
    } else {
      gl_.glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, w, h, 0, GL_RED, GL_FLOAT, texels.data());
    }
    setSingleLevelSampling(gl_, GL_LINEAR, target,
                           addressing == CookieAddressing::Repeat ? GL_REPEAT : GL_CLAMP_TO_EDGE);
    gl_.glBindTexture(target, 0);
    gl_.check(("uploading light '" + lights[l].name + "''s cookie").c_str());
  }
  uploadMilliseconds_ =
      any ? std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() : 0.0;
  textures_ = std::move(textures);
  scene_ = prepared;
}

}  // namespace backends::gl
