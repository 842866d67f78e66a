#include "lighting/light_space.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace lighting {
namespace {

// One face of the cube: the major axis and its sign, and the world axes (with
// signs) that sc and tc read, as in Vulkan's "Cube Map Face Selection" table.
struct FaceAxes {
  int major;
  double sign;
  int sAxis;
  double sSign;
  int tAxis;
  double tSign;
};
constexpr FaceAxes kFaces[kCubeFaceCount] = {
    {0, +1, 2, -1, 1, -1},  // +X: sc = -z, tc = -y
    {0, -1, 2, +1, 1, -1},  // -X: sc = +z, tc = -y
    {1, +1, 0, +1, 2, +1},  // +Y: sc = +x, tc = +z
    {1, -1, 0, +1, 2, -1},  // -Y: sc = +x, tc = -z
    {2, +1, 0, +1, 1, -1},  // +Z: sc = +x, tc = -y
    {2, -1, 0, -1, 1, -1},  // -Z: sc = -x, tc = -y
};

}  // namespace

LightBasis lightBasis(const Vec3& direction) {
  LightBasis b;
  b.f = glm::normalize(direction);
  const Vec3 up = std::abs(b.f.y) > kBasisUpSwitch ? Vec3(0, 0, 1) : Vec3(0, 1, 0);
  b.r = glm::normalize(glm::cross(b.f, up));
  b.u = glm::cross(b.r, b.f);
  return b;
}

CubeFacePoint cubeFacePoint(const Vec3& d) {
  const Vec3 m = glm::abs(d);
  int face;
  if (m.x >= m.y && m.x >= m.z) face = d.x >= 0 ? 0 : 1;
  else if (m.y >= m.z) face = d.y >= 0 ? 2 : 3;
  else face = d.z >= 0 ? 4 : 5;
  const FaceAxes& a = kFaces[face];
  CubeFacePoint c;
  c.face = face;
  c.major = m[a.major];
  c.u = (a.sSign * d[a.sAxis] / c.major + 1.0) / 2.0;
  c.v = (a.tSign * d[a.tAxis] / c.major + 1.0) / 2.0;
  return c;
}

CubeFaceFrame cubeFaceFrame(int face) {
  const FaceAxes& a = kFaces[face];
  CubeFaceFrame frame{Vec3(0.0), Vec3(0.0), Vec3(0.0)};
  frame.axis[a.major] = a.sign;
  frame.sAxis[a.sAxis] = a.sSign;
  frame.tAxis[a.tAxis] = a.tSign;
  return frame;
}

Vec3 cubeFaceDirection(int face, double s, double t) {
  const CubeFaceFrame frame = cubeFaceFrame(face);
  return frame.axis + s * frame.sAxis + t * frame.tAxis;
}

CubeTexel cubeTexelAcrossEdge(int face, int i, int j, int n) {
  CubeTexel texel{face, i, j, false};
  const bool outI = i < 0 || i >= n, outJ = j < 0 || j >= n;
  if (!outI && !outJ) return texel;
  if (outI && outJ) {
    texel.corner = true;
    texel.i = std::clamp(i, 0, n - 1);
    texel.j = std::clamp(j, 0, n - 1);
    return texel;
  }
  const int ci = std::clamp(i, 0, n - 1), cj = std::clamp(j, 0, n - 1);
  const double s = 2.0 * (ci + 0.5) / n - 1.0, t = 2.0 * (cj + 0.5) / n - 1.0;
  // Pulled in from the edge by a texel's width, pushed onto the edge along
  // the axis that left the face: the major axis of the point across it.
  const CubeFaceFrame frame = cubeFaceFrame(face);
  const Vec3 edge = outI ? frame.sAxis * (ci < n / 2 ? -1.0 : 1.0) : frame.tAxis * (cj < n / 2 ? -1.0 : 1.0);
  const Vec3 along = outI ? frame.tAxis * t : frame.sAxis * s;
  const CubeFacePoint across = cubeFacePoint(frame.axis * (1.0 - 1.0 / n) + edge + along);
  texel.face = across.face;
  texel.i = std::clamp(int(std::floor(across.u * n)), 0, n - 1);
  texel.j = std::clamp(int(std::floor(across.v * n)), 0, n - 1);
  return texel;
}

}  // namespace lighting
