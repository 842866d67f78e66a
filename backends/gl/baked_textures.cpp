#include "backends/gl/baked_textures.h"

#include "backends/backend.h"
#include "backends/gl/forward_programs.h"

#include <stdexcept>
#include <string>

namespace backends::gl {
namespace {

// Desktop OpenGL 3.0 and later filter float textures (only OpenGL ES makes
// that an extension), so a 3.3 context may be trusted; from 4.3 on the driver
// can be asked, and a driver that says it cannot is refused rather than
// left to sample the maps as NEAREST or as black.
void requireFloatFiltering(const GlFunctions& gl) {
  GLint major = 0, minor = 0;
  gl.glGetIntegerv(GL_MAJOR_VERSION, &major);
  gl.glGetIntegerv(GL_MINOR_VERSION, &minor);
  if (major * 10 + minor < 43 || !gl.glGetInternalformativ) return;
  GLint support = GL_NONE;
  gl.glGetInternalformativ(GL_TEXTURE_2D, GL_RGBA32F, GL_FILTER, 1, &support);
  gl.check("asking whether RGBA32F textures can be filtered");
  if (support != GL_FULL_SUPPORT && support != GL_CAVEAT_SUPPORT)
    throw NotSupportedError("the GL driver cannot filter RGBA32F textures with GL_LINEAR, which the baked maps "
                            "need (SPEC 3.6)");
}

}  // namespace

BakedTextures::BakedTextures(const GlFunctions& gl) : gl_(gl) {
  requireFloatFiltering(gl_);
  gl_.glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize_);
  lighting::TexelMap unlit{1, {0.0f, 0.0f, 0.0f, 1.0f}};
  lighting::TexelMap unmasked{1, {1.0f, 1.0f, 1.0f, 1.0f}};
  noLightmap_ = upload(unlit, "the stand-in lightmap");
  noShadowMask_ = upload(unmasked, "the stand-in shadow mask");
}

void BakedTextures::update(const lighting::PreparedScene& scene) {
  if (scene.baked && scene.baked == uploaded_) return;
  // Without a bake this loop is what refuses a scene that needed one
  // (bakeOf throws), instead of drawing it with the stand-ins.
  std::vector<ObjectTextures> objects(scene.scene.objects.size());
  for (std::size_t o = 0; o < objects.size(); ++o) {
    const lighting::ObjectBake* bake = scene.bakeOf(int(o));
    if (!bake) continue;
    const std::string name = "object " + std::to_string(o) + "'s ";
    if (!bake->lightmap.empty()) objects[o].lightmap = upload(bake->lightmap, (name + "lightmap").c_str());
    if (!bake->shadowMask.empty()) objects[o].shadowMask = upload(bake->shadowMask, (name + "shadow mask").c_str());
  }
  objects_ = std::move(objects);
  uploaded_ = scene.baked;
}

void BakedTextures::bind(int object) const {
  const bool known = object >= 0 && std::size_t(object) < objects_.size();
  const GLuint lightmap = known && objects_[object].lightmap.get() ? objects_[object].lightmap.get() : noLightmap_.get();
  const GLuint mask = known && objects_[object].shadowMask.get() ? objects_[object].shadowMask.get() : noShadowMask_.get();
  gl_.glActiveTexture(GL_TEXTURE0 + shaders::binding::kLightmapTexture.glUnit());
  gl_.glBindTexture(GL_TEXTURE_2D, lightmap);
  gl_.glActiveTexture(GL_TEXTURE0 + shaders::binding::kShadowMaskTexture.glUnit());
  gl_.glBindTexture(GL_TEXTURE_2D, mask);
}

GlName BakedTextures::upload(const lighting::TexelMap& map, const char* what) const {
  const int n = map.resolution;
  if (map.texels.size() != std::size_t(n) * std::size_t(n) * 4)
    throw std::logic_error(std::string(what) + " has " + std::to_string(map.texels.size()) + " floats, not " +
                           std::to_string(n) + " x " + std::to_string(n) + " x 4");
  if (n > maxSize_)
    throw NotSupportedError(std::string(what) + " is " + std::to_string(n) + " texels wide; the GL driver's limit is " +
                            std::to_string(maxSize_));
  GlName texture = makeTexture(gl_);
  gl_.glActiveTexture(GL_TEXTURE0);
  gl_.glBindTexture(GL_TEXTURE_2D, texture.get());
  // Rows of N RGBA floats are tightly packed and 4-byte aligned.
  gl_.glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  // Texel (i, j) is element j * N + i: GL's row j is the map's row j, which
  // is what v = (j + 0.5) / N addresses, so nothing is flipped.
  gl_.glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, n, n, 0, GL_RGBA, GL_FLOAT, map.texels.data());
  setSingleLevelSampling(gl_, GL_LINEAR);  // SPEC 3.6: bilinear, clamp to edge
  gl_.glBindTexture(GL_TEXTURE_2D, 0);
  gl_.check((std::string("uploading ") + what).c_str());
  return texture;
}

}  // namespace backends::gl
