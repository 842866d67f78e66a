#include "backends/cookie_texels.h"

namespace backends {

CookieAddressing cookieAddressing(const lighting::Light& light) {
  switch (light.type) {
    case lighting::LightType::Directional: return CookieAddressing::Repeat;
    case lighting::LightType::Spot: return CookieAddressing::ClampToEdge;
    case lighting::LightType::Point: return CookieAddressing::Cube;
  }
  return CookieAddressing::ClampToEdge;
}

std::vector<float> cookieTexels(const lighting::Cookie& cookie) {
  std::vector<float> texels;
  for (const auto& image : cookie.images) texels.insert(texels.end(), image->texels.begin(), image->texels.end());
  return texels;
}

int cookieWidth(const lighting::Cookie& cookie) { return cookie.images.front()->width; }
int cookieHeight(const lighting::Cookie& cookie) { return cookie.images.front()->height; }

}  // namespace backends
