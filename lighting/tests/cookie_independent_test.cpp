// SPEC 3.10 (light cookies) evaluated independently, from the SPEC text alone,
// and compared with lighting::cookieValue / lighting::cookieCoordinates.
//
// Nothing below calls into lighting/ for the evaluation: the basis (SPEC 3.9),
// the coordinates (SPEC 3.10), the cube face table and the bilinear filter with
// repeat / clamp-to-edge are written here again, component by component, with
// no glm helpers (glm is only used for Vec3 storage and to build test points).
//
// The acceptance rule: 1e-9 relative in double, or 1e-12 absolute
// where the expected value is 0; values behind a spot's apex must be exactly 0.
// Where a point lies far from the origin (near 1e5 m) the comparison of a
// general direction also admits the coordinate's own double-precision error
// times the cookie's gradient, derived in DirectionalFarFromTheOrigin below.
#include "lighting/cookie.h"
#include "lighting/scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <memory>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace {

using lighting::Cookie;
using lighting::CookieImage;
using lighting::Light;
using lighting::LightType;
using lighting::Vec3;

constexpr double kRel = 1e-9;    // relative agreement demanded
constexpr double kAbs = 1e-12;   // absolute agreement where the expected value is 0
constexpr double kEps = std::numeric_limits<double>::epsilon();  // 2^-52
constexpr double kPi = 3.14159265358979323846;

// ---------------------------------------------------------------------------
// The independent evaluation of SPEC 3.10.
// ---------------------------------------------------------------------------
namespace ref {

double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return Vec3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
Vec3 unit(const Vec3& a) {
  const double len = std::sqrt(dot(a, a));
  return Vec3(a.x / len, a.y / len, a.z / len);
}
Vec3 sub(const Vec3& a, const Vec3& b) { return Vec3(a.x - b.x, a.y - b.y, a.z - b.z); }

// SPEC 3.9: f = direction, r = normalize(cross(f, up)), u = cross(r, f),
// up = +Y, or +Z when |f.y| > 0.99.
struct Basis {
  Vec3 r, u, f;
};
Basis basis(const Vec3& direction) {
  Basis b;
  b.f = unit(direction);
  const Vec3 up = std::fabs(b.f.y) > 0.99 ? Vec3(0, 0, 1) : Vec3(0, 1, 0);
  b.r = unit(cross(b.f, up));
  b.u = cross(b.r, b.f);
  return b;
}

enum class Address { Repeat, ClampToEdge };

long long address(long long i, int n, Address mode) {
  if (mode == Address::Repeat) return ((i % n) + n) % n;
  return std::clamp<long long>(i, 0, n - 1);
}

double texel(const CookieImage& im, long long i, long long j) {
  return double(im.texels[std::size_t(j) * std::size_t(im.width) + std::size_t(i)]);
}

// Bilinear at mip level 0 with the texel centre of (i, j) at ((i+0.5)/W, (j+0.5)/H),
// row 0 at v = 0: x = s W - 0.5, i0 = floor(x), alpha = x - i0 (Vulkan's
// "Texel Coordinate Systems, Linear Filtering"), same in t.
double bilinear(const CookieImage& im, double s, double t, Address mode) {
  const double x = s * im.width - 0.5, y = t * im.height - 0.5;
  const double fx = std::floor(x), fy = std::floor(y);
  const double a = x - fx, b = y - fy;
  const long long i0 = static_cast<long long>(fx), j0 = static_cast<long long>(fy);
  const long long ia = address(i0, im.width, mode), ib = address(i0 + 1, im.width, mode);
  const long long ja = address(j0, im.height, mode), jb = address(j0 + 1, im.height, mode);
  return (1 - a) * (1 - b) * texel(im, ia, ja) + a * (1 - b) * texel(im, ib, ja) +
         (1 - a) * b * texel(im, ia, jb) + a * b * texel(im, ib, jb);
}

// Directional: (dot(p, r)/w, dot(p, u)/h), not wrapped here (the sampler repeats).
struct UV {
  double u = 0, v = 0;
};
UV directionalUV(const Light& light, const Vec3& p) {
  const Basis b = basis(light.direction);
  return {dot(p, b.r) / light.cookie->sizeX, dot(p, b.u) / light.cookie->sizeY};
}
double directionalValue(const Light& light, const Vec3& p) {
  const UV uv = directionalUV(light, p);
  return bilinear(*light.cookie->images[0], uv.u, uv.v, Address::Repeat);
}

// Spot: q = (dot(d, r), dot(d, u), dot(d, f)), d = p - position;
// uv = 0.5 + 0.5 q.xy / (q.z tan(spot_angle/2)) (spot_angle the full cone),
// clamp to edge, 0 where q.z <= 0.
struct SpotUV {
  bool behind = false;
  double u = 0, v = 0;
};
SpotUV spotUV(const Light& light, const Vec3& p) {
  const Basis b = basis(light.direction);
  const Vec3 d = sub(p, light.position);
  const double qx = dot(d, b.r), qy = dot(d, b.u), qz = dot(d, b.f);
  if (qz <= 0) return {true, 0, 0};
  const double t = std::tan(light.spotAngleDeg * kPi / 360.0);
  return {false, 0.5 + 0.5 * qx / (qz * t), 0.5 + 0.5 * qy / (qz * t)};
}
double spotValue(const Light& light, const Vec3& p) {
  const SpotUV uv = spotUV(light, p);
  if (uv.behind) return 0.0;
  return bilinear(*light.cookie->images[0], uv.u, uv.v, Address::ClampToEdge);
}

// Point: the cube sampled in the direction p - position (world axes).
// Face selection, from the Vulkan specification, "Cube Map Face Selection",
// table "Cube map face and coordinate selection" (KhronosGroup/Vulkan-Docs,
// chapters/textures.adoc; OpenGL's table is the same):
//
//   major axis   layer  face        sc     tc     rc
//   +rx          0      Positive X  -rz    -ry    rx
//   -rx          1      Negative X  +rz    -ry    rx
//   +ry          2      Positive Y  +rx    +rz    ry
//   -ry          3      Negative Y  +rx    -rz    ry
//   +rz          4      Positive Z  +rx    -ry    rz
//   -rz          5      Negative Z  -rx    -ry    rz
//
//   s_face = 1/2 * sc/|rc| + 1/2,  t_face = 1/2 * tc/|rc| + 1/2
//
// The same text says ties of magnitude should go to rz over ry and rx, then ry
// over rx (implementations may choose other deterministic rules, so the tests
// below never put a direction on a tie).
struct FaceUV {
  int face = 0;
  double u = 0, v = 0;
};
FaceUV cubeFace(const Vec3& d) {
  const double ax = std::fabs(d.x), ay = std::fabs(d.y), az = std::fabs(d.z);
  int face;
  double sc, tc, rc;
  if (az >= ax && az >= ay) {
    rc = az;
    if (d.z >= 0) { face = 4; sc = d.x; tc = -d.y; }
    else          { face = 5; sc = -d.x; tc = -d.y; }
  } else if (ay >= ax) {
    rc = ay;
    if (d.y >= 0) { face = 2; sc = d.x; tc = d.z; }
    else          { face = 3; sc = d.x; tc = -d.z; }
  } else {
    rc = ax;
    if (d.x >= 0) { face = 0; sc = -d.z; tc = -d.y; }
    else          { face = 1; sc = d.z; tc = -d.y; }
  }
  return {face, 0.5 * sc / rc + 0.5, 0.5 * tc / rc + 0.5};
}
FaceUV pointUV(const Light& light, const Vec3& p) { return cubeFace(sub(p, light.position)); }
// Within one face only: the tests keep every bilinear footprint inside the face
// (at a texel centre of the first or last row/column the out-of-face tap has
// weight 0, up to rounding), so clamping within the face is exact there, and
// the seamless rule across face edges is not exercised.
double pointValue(const Light& light, const Vec3& p) {
  const FaceUV f = pointUV(light, p);
  return bilinear(*light.cookie->images[std::size_t(f.face)], f.u, f.v, Address::ClampToEdge);
}

// The inverse of the table: the direction (major component of magnitude 1)
// that face `face` maps to (u, v).
Vec3 cubeDirection(int face, double u, double v) {
  const double s = 2 * u - 1, t = 2 * v - 1;
  switch (face) {
    case 0: return Vec3(1, -t, -s);
    case 1: return Vec3(-1, -t, s);
    case 2: return Vec3(s, 1, t);
    case 3: return Vec3(s, -1, -t);
    case 4: return Vec3(s, -t, 1);
    default: return Vec3(-s, -t, -1);
  }
}

}  // namespace ref

// ---------------------------------------------------------------------------
// Test scaffolding.
// ---------------------------------------------------------------------------

// Distinct texel values in [0.1, 0.9] (never 0 or 1): the golden-ratio
// sequence, k-th value 0.1 + 0.8 frac(k phi).
std::shared_ptr<const CookieImage> makeImage(int w, int h, int seed) {
  auto im = std::make_shared<CookieImage>();
  im->width = w;
  im->height = h;
  for (int k = 0; k < w * h; ++k) {
    const double g = (k + 1 + 97 * seed) * 0.6180339887498949;
    im->texels.push_back(float(0.1 + 0.8 * (g - std::floor(g))));
  }
  return im;
}

Light makeLight(LightType type, const Vec3& position, const Vec3& direction,
                std::vector<std::shared_ptr<const CookieImage>> images, double sizeX = 1, double sizeY = 1) {
  Light l;
  l.name = "cookie-independent";
  l.type = type;
  l.position = position;
  l.direction = ref::unit(direction);  // the loader normalises it
  Cookie c;
  for (std::size_t i = 0; i < images.size(); ++i) c.files.push_back("in-memory-" + std::to_string(i));
  c.images = std::move(images);
  c.sizeX = sizeX;
  c.sizeY = sizeY;
  l.cookie = c;
  return l;
}

// The largest difference found, relative to the expected value.
struct Diff {
  const char* what;
  double maxRel = 0;
  ~Diff() { std::printf("[ max rel diff ] %s: %.3g\n", what, maxRel); }
  void note(double got, double want) {
    if (want != 0) maxRel = std::max(maxRel, std::fabs(got - want) / std::fabs(want));
  }
};

// |got - want| <= 1e-9 |want|, or 1e-12 where want is 0, plus `extra`.
::testing::AssertionResult close(double got, double want, double extra = 0) {
  const double tol = (want == 0 ? kAbs : kRel * std::fabs(want)) + extra;
  if (std::fabs(got - want) <= tol) return ::testing::AssertionSuccess();
  char buf[200];
  std::snprintf(buf, sizeof buf, "got %.17g, want %.17g, diff %.3g > tol %.3g", got, want, std::fabs(got - want), tol);
  return ::testing::AssertionFailure() << buf;
}

std::string at(const Vec3& p) {
  char buf[120];
  std::snprintf(buf, sizeof buf, "p = (%.17g, %.17g, %.17g)", p.x, p.y, p.z);
  return buf;
}

double len(const Vec3& a) { return std::sqrt(ref::dot(a, a)); }

struct Rng {
  std::mt19937_64 g{0x5eed'c00c1eULL};
  double uniform(double lo, double hi) { return lo + (hi - lo) * double(g() >> 11) * 0x1.0p-53; }
};

// The largest change of the bilinear value per unit of u (and v): one texel's
// width is 1/W, so W times the largest step between neighbours (wrapping).
struct Gradient {
  double du = 0, dv = 0;
};
Gradient gradient(const CookieImage& im) {
  Gradient g;
  for (int j = 0; j < im.height; ++j)
    for (int i = 0; i < im.width; ++i) {
      g.du = std::max(g.du, std::fabs(ref::texel(im, (i + 1) % im.width, j) - ref::texel(im, i, j)));
      g.dv = std::max(g.dv, std::fabs(ref::texel(im, i, (j + 1) % im.height) - ref::texel(im, i, j)));
    }
  g.du *= im.width;
  g.dv *= im.height;
  return g;
}

TEST(CookieIndependent, TexelValuesAreDistinctAndNeitherZeroNorOne) {
  std::set<float> seen;
  for (int seed = 0; seed < 8; ++seed) {
    const auto im = makeImage(6, 6, seed);
    for (float t : im->texels) {
      EXPECT_GT(t, 0.05f);
      EXPECT_LT(t, 0.95f);
      EXPECT_TRUE(seen.insert(t).second) << t;
    }
  }
}

// ---------------------------------------------------------------------------
// The basis (SPEC 3.9) that the directional and spot cookies use.
// ---------------------------------------------------------------------------
TEST(CookieIndependent, LightBasisMatchesSpec39OnBothUpVectors) {
  const Vec3 dirs[] = {{-0.4, -0.7, 0.59}, {0.3, -0.8, 0.45}, {1, 0, 0},     {0, 0, -1},
                       {0.06, -1, -0.07},  {0.05, 1, 0.09},   {0, -1, 0},    {0, 1, 0},
                       {0.1, -0.985, 0.13}, {0.02, 0.9899, -0.11}};
  for (const Vec3& d0 : dirs) {
    const Vec3 d = ref::unit(d0);
    const ref::Basis want = ref::basis(d);
    const lighting::LightBasis got = lighting::lightBasis(d);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(got.r[k], want.r[k], kAbs) << at(d) << " r[" << k << "]";
      EXPECT_NEAR(got.u[k], want.u[k], kAbs) << at(d) << " u[" << k << "]";
      EXPECT_NEAR(got.f[k], want.f[k], kAbs) << at(d) << " f[" << k << "]";
    }
  }
}

// ---------------------------------------------------------------------------
// Directional: tiled, repeating in both axes.
// ---------------------------------------------------------------------------
struct DirectionalCase {
  const char* name;
  Vec3 direction;
  double w, h;
  int W, H;
};
const DirectionalCase kDirectional[] = {
    {"general direction, 4x3 image, tile 1.5 x 0.75", {-0.4, -0.7, 0.59}, 1.5, 0.75, 4, 3},
    {"|f.y| > 0.99 (up = +Z), 3x5 image, tile 2 x 3", {0.06, -1, -0.07}, 2.0, 3.0, 3, 5},
    {"axis-aligned (1, 0, 0), 4x3 image, tile 0.7 x 1.3", {1, 0, 0}, 0.7, 1.3, 4, 3},
};

// A point whose directional cookie coordinates are (U, V), at depth `depth`
// along f, built from this file's basis.
Vec3 directionalPoint(const Light& l, double U, double V, double depth) {
  const ref::Basis b = ref::basis(l.direction);
  const double a = U * l.cookie->sizeX, c = V * l.cookie->sizeY;
  return Vec3(a * b.r.x + c * b.u.x + depth * b.f.x, a * b.r.y + c * b.u.y + depth * b.f.y,
              a * b.r.z + c * b.u.z + depth * b.f.z);
}

// The coordinates' own double error (see DirectionalFarFromTheOrigin): this
// file's and the implementation's dot(p, r)/w may differ by 16 eps |p| / w.
double directionalCoordTol(const Vec3& p, double size) { return std::max(kAbs, 16 * kEps * len(p) / size); }
// What that coordinate error can do to the value: the image's largest gradient
// times it. Within 100 m of the origin it is below ~2e-11 (a fiftieth of the
// 1e-9 relative on values >= 0.1); it only matters thousands of tiles away.
double directionalSlack(const Light& l, const Vec3& p) {
  const Gradient g = gradient(*l.cookie->images[0]);
  return g.du * directionalCoordTol(p, l.cookie->sizeX) + g.dv * directionalCoordTol(p, l.cookie->sizeY);
}

TEST(CookieIndependent, DirectionalTexelCentresManyRepeatsAway) {
  Diff diff{"directional texel centres"};
  Rng rng;
  const long long tiles[] = {0, 1, -1, 7, -13, 250, -4096, 31337};
  int seed = 0;
  for (const DirectionalCase& dc : kDirectional) {
    SCOPED_TRACE(dc.name);
    const auto im = makeImage(dc.W, dc.H, seed++);
    const Light l = makeLight(LightType::Directional, {3, 7, -2}, dc.direction, {im}, dc.w, dc.h);
    for (long long n : tiles)
      for (long long m : {0LL, -1LL, 3LL, -777LL})
        for (int j = 0; j < dc.H; ++j)
          for (int i = 0; i < dc.W; ++i) {
            const double U = double(n) + (i + 0.5) / dc.W, V = double(m) + (j + 0.5) / dc.H;
            const Vec3 p = directionalPoint(l, U, V, rng.uniform(-20, 20));
            const ref::UV want = ref::directionalUV(l, p);
            const lighting::CookieCoordinates got = lighting::cookieCoordinates(l, p);
            EXPECT_FALSE(got.outside) << at(p);
            EXPECT_EQ(got.face, 0) << at(p);
            EXPECT_NEAR(got.u, want.u, directionalCoordTol(p, dc.w)) << at(p);
            EXPECT_NEAR(got.v, want.v, directionalCoordTol(p, dc.h)) << at(p);
            const double value = lighting::cookieValue(l, p);
            const double mine = ref::directionalValue(l, p);
            // Both against this file's evaluation and against the texel itself.
            const double slack = directionalSlack(l, p);
            EXPECT_TRUE(close(value, mine, slack)) << at(p) << " tile (" << n << ", " << m << ") texel " << i << "," << j;
            EXPECT_TRUE(close(value, ref::texel(*im, i, j), slack)) << at(p) << " texel " << i << "," << j;
            EXPECT_TRUE(close(mine, ref::texel(*im, i, j), slack)) << "self-check " << at(p);
            diff.note(value, mine);
          }
  }
}

TEST(CookieIndependent, DirectionalBilinearRepeatsAcrossTileSeams) {
  Diff diff{"directional bilinear"};
  Rng rng;
  int seed = 0;
  for (const DirectionalCase& dc : kDirectional) {
    SCOPED_TRACE(dc.name);
    const auto im = makeImage(dc.W, dc.H, seed++);
    const Light l = makeLight(LightType::Directional, {3, 7, -2}, dc.direction, {im}, dc.w, dc.h);
    std::vector<std::pair<double, double>> uvs;
    for (int k = 0; k < 400; ++k) uvs.push_back({rng.uniform(-60, 60), rng.uniform(-60, 60)});
    // Within half a texel of a tile seam: the four taps wrap (W-1 with 0, H-1 with 0).
    for (double n : {-3.0, 0.0, 1.0, 42.0})
      for (double e : {0.1, 0.25, 0.4})
        for (double s : {-1.0, 1.0}) {
          uvs.push_back({n + s * e / dc.W, n + 0.3 + 0.5 / dc.H});
          uvs.push_back({n + 0.3 + 0.5 / dc.W, n + s * e / dc.H});
          uvs.push_back({n + s * e / dc.W, n - s * e / dc.H});
        }
    for (auto [U, V] : uvs) {
      const Vec3 p = directionalPoint(l, U, V, rng.uniform(-20, 20));
      const double value = lighting::cookieValue(l, p);
      const double mine = ref::directionalValue(l, p);
      EXPECT_TRUE(close(value, mine, directionalSlack(l, p))) << at(p) << " uv (" << U << ", " << V << ")";
      diff.note(value, mine);
      const lighting::CookieCoordinates got = lighting::cookieCoordinates(l, p);
      const ref::UV want = ref::directionalUV(l, p);
      EXPECT_NEAR(got.u, want.u, directionalCoordTol(p, dc.w)) << at(p);
      EXPECT_NEAR(got.v, want.v, directionalCoordTol(p, dc.h)) << at(p);
    }
  }
  // A hand check of the repeat at a seam: U = 5 - 1/16, a quarter texel below a
  // tile edge: x = 4 U - 0.5 = 19.25, taps 19 mod 4 = 3 and 20 mod 4 = 0 with
  // weights 0.75 and 0.25; V = -1.5 is the centre of row (-5 mod 3) = 1.
  const auto im = makeImage(4, 3, 11);
  const Light l = makeLight(LightType::Directional, {0, 0, 0}, {-0.4, -0.7, 0.59}, {im}, 1.5, 0.75);
  const Vec3 p = directionalPoint(l, 5.0 - 0.25 / 4, -2.0 + 1.5 / 3, 0.5);
  const double want = 0.75 * ref::texel(*im, 3, 1) + 0.25 * ref::texel(*im, 0, 1);
  EXPECT_TRUE(close(lighting::cookieValue(l, p), want)) << at(p);
}

// Near 1e5 m from the origin. The spacing of doubles there is
// ulp(1e5) = 2^(16-52) = 2^-36 ~ 1.46e-11 m (eps = 2^-52 ~ 2.2e-16 relative).
// dot(p, r) over three products and two sums is within 3 eps |p| of the exact
// dot product with the computed r (|r| = 1, Cauchy-Schwarz), and the computed r
// is within ~3 eps of the exact unit vector, adding 3 eps |p|; so each of two
// independent evaluations is within ~6 eps |p| / w (tile units) of the exact
// coordinate and they may differ by 12 eps |p| / w; 16 eps |p| / w is used.
// At |p| = 1.2e5 and w = 1.5 that is ~2.8e-10 tiles, and with a gradient of
// W * max|texel step| ~ 3 per tile the value is known only to ~1e-9 absolute:
// ~1e-8 relative for values ~0.1, so 1e-9 relative cannot be promised for a
// general direction there. The honest comparison is therefore:
//  - general direction: |value - mine| <= 1e-9 |mine| + Gu du + Gv dv, with du,
//    dv the coordinate bounds above and Gu, Gv the image's largest gradients;
//    the coordinates themselves to du, dv (absolute, in tiles);
//  - an axis-aligned light (0, -1, 0), whose basis r = (-1, 0, 0), u = (0, 0, 1)
//    is exact in double, with power-of-two tile sizes and images, at points whose
//    coordinates are dyadic: every step is exact, so 1e-9 relative holds there
//    with nothing added (the texel centres are hit exactly).
TEST(CookieIndependent, DirectionalFarFromTheOrigin) {
  Diff diffGeneral{"directional near 1e5 m, general direction (vs 1e-9 rel + gradient * coordinate error)"};
  Diff diffExact{"directional near 1e5 m, exact basis"};
  Rng rng;
  {
    const auto im = makeImage(4, 3, 21);
    const Light l = makeLight(LightType::Directional, {0, 0, 0}, {-0.4, -0.7, 0.59}, {im}, 1.5, 0.75);
    const Gradient g = gradient(*im);
    for (int k = 0; k < 300; ++k) {
      // |p| between ~9e4 and ~1.4e5: 6e4 to 9e4 m along each of r, u and f.
      const bool centre = k % 2 == 0;
      const double sn = k % 4 < 2 ? 1 : -1, sm = k % 3 == 0 ? -1 : 1, sd = k % 5 < 2 ? -1 : 1;
      const double n = sn * std::floor(rng.uniform(4e4, 6e4)), m = sm * std::floor(rng.uniform(8e4, 1.2e5));
      const int i = int(rng.uniform(0, 4)), j = int(rng.uniform(0, 3));
      const double U = centre ? n + (i + 0.5) / 4 : n + rng.uniform(0, 1);
      const double V = centre ? m + (j + 0.5) / 3 : m + rng.uniform(0, 1);
      const Vec3 p = directionalPoint(l, U, V, sd * rng.uniform(6e4, 9e4));
      ASSERT_GT(len(p), 9e4);
      const double du = directionalCoordTol(p, 1.5), dv = directionalCoordTol(p, 0.75);
      const lighting::CookieCoordinates got = lighting::cookieCoordinates(l, p);
      const ref::UV want = ref::directionalUV(l, p);
      EXPECT_NEAR(got.u, want.u, du) << at(p);
      EXPECT_NEAR(got.v, want.v, dv) << at(p);
      const double value = lighting::cookieValue(l, p);
      const double mine = ref::directionalValue(l, p);
      EXPECT_TRUE(close(value, mine, g.du * du + g.dv * dv)) << at(p);
      if (centre) {
        EXPECT_TRUE(close(value, ref::texel(*im, i, j), g.du * du + g.dv * dv)) << at(p);
      }
      diffGeneral.note(value, mine);
    }
  }
  {
    const auto im = makeImage(4, 4, 22);
    const Light l = makeLight(LightType::Directional, {0, 0, 0}, {0, -1, 0}, {im}, 0.5, 0.25);
    for (int k = 0; k < 300; ++k) {
      // U in tiles: dyadic, |U w| ~ 1e5. p.x = -U w (r = (-1, 0, 0)), p.z = V h (u = (0, 0, 1)).
      const bool centre = k % 2 == 0;
      const double n = std::floor(rng.uniform(1.6e5, 2.4e5)) * (k % 4 < 2 ? 1 : -1);
      const double m = std::floor(rng.uniform(2.8e5, 4.4e5)) * (k % 3 == 0 ? -1 : 1);
      const int i = int(rng.uniform(0, 4)), j = int(rng.uniform(0, 4));
      const double U = centre ? n + (i + 0.5) / 4 : n + std::floor(rng.uniform(0, 64)) / 64;
      const double V = centre ? m + (j + 0.5) / 4 : m + std::floor(rng.uniform(0, 64)) / 64;
      const Vec3 p(-U * 0.5, std::floor(rng.uniform(-1e5, 1e5)), V * 0.25);
      ASSERT_GT(len(p), 7e4);
      const lighting::CookieCoordinates got = lighting::cookieCoordinates(l, p);
      EXPECT_NEAR(got.u, U, directionalCoordTol(p, 0.5)) << at(p);
      EXPECT_NEAR(got.v, V, directionalCoordTol(p, 0.25)) << at(p);
      const ref::UV want = ref::directionalUV(l, p);
      EXPECT_EQ(want.u, U) << "self-check " << at(p);
      EXPECT_EQ(want.v, V) << "self-check " << at(p);
      const double value = lighting::cookieValue(l, p);
      const double mine = ref::directionalValue(l, p);
      EXPECT_TRUE(close(value, mine)) << at(p);
      if (centre) {
        EXPECT_TRUE(close(value, ref::texel(*im, i, j))) << at(p);
      }
      diffExact.note(value, mine);
    }
  }
}

// ---------------------------------------------------------------------------
// Spot: projected over the cone, clamp to edge, 0 behind the apex.
// ---------------------------------------------------------------------------
struct SpotCase {
  const char* name;
  Vec3 position, direction;
  double angle;
  int W, H;
};
const SpotCase kSpot[] = {
    {"general direction, 50 deg, 5x4", {1.25, 3.5, -0.75}, {0.3, -0.8, 0.45}, 50, 5, 4},
    {"|f.y| > 0.99 (up = +Z), 170 deg, 4x6", {-2, 6, 1}, {0.06, -1, -0.07}, 170, 4, 6},
    {"narrow 7.5 deg, pointing up and sideways, 3x3", {0.5, -1, 2}, {-0.55, 0.35, -0.76}, 7.5, 3, 3},
};

// The point at cookie coordinates (u, v), at depth q.z = z, from this file's basis.
Vec3 spotPoint(const Light& l, double u, double v, double z) {
  const ref::Basis b = ref::basis(l.direction);
  const double t = std::tan(l.spotAngleDeg * kPi / 360.0);
  const double x = (2 * u - 1) * t * z, y = (2 * v - 1) * t * z;
  return Vec3(l.position.x + x * b.r.x + y * b.u.x + z * b.f.x, l.position.y + x * b.r.y + y * b.u.y + z * b.f.y,
              l.position.z + x * b.r.z + y * b.u.z + z * b.f.z);
}

Light spotLight(const SpotCase& sc, int seed) {
  Light l = makeLight(LightType::Spot, sc.position, sc.direction, {makeImage(sc.W, sc.H, seed)});
  l.spotAngleDeg = sc.angle;
  l.range = 9;
  return l;
}

TEST(CookieIndependent, SpotTexelCentres) {
  Diff diff{"spot texel centres"};
  int seed = 30;
  for (const SpotCase& sc : kSpot) {
    SCOPED_TRACE(sc.name);
    const Light l = spotLight(sc, seed++);
    const CookieImage& im = *l.cookie->images[0];
    for (double z : {0.05, 0.4, 2.0, 7.3, 25.0})  // inside and beyond the range: the cookie does not care
      for (int j = 0; j < sc.H; ++j)
        for (int i = 0; i < sc.W; ++i) {
          const double u = (i + 0.5) / sc.W, v = (j + 0.5) / sc.H;
          const Vec3 p = spotPoint(l, u, v, z);
          const ref::SpotUV want = ref::spotUV(l, p);
          ASSERT_FALSE(want.behind);
          const lighting::CookieCoordinates got = lighting::cookieCoordinates(l, p);
          EXPECT_FALSE(got.outside) << at(p);
          EXPECT_EQ(got.face, 0) << at(p);
          EXPECT_TRUE(close(got.u, want.u)) << at(p);
          EXPECT_TRUE(close(got.v, want.v)) << at(p);
          EXPECT_TRUE(close(want.u, u)) << "self-check " << at(p);
          EXPECT_TRUE(close(want.v, v)) << "self-check " << at(p);
          const double value = lighting::cookieValue(l, p);
          const double mine = ref::spotValue(l, p);
          EXPECT_TRUE(close(value, mine)) << at(p) << " texel " << i << "," << j << " depth " << z;
          EXPECT_TRUE(close(value, ref::texel(im, i, j))) << at(p) << " texel " << i << "," << j;
          diff.note(value, mine);
        }
  }
}

TEST(CookieIndependent, SpotBilinearInsideAndClampedOutsideTheCone) {
  Diff diff{"spot bilinear (inside and outside the cone)"};
  Rng rng;
  int seed = 40;
  for (const SpotCase& sc : kSpot) {
    SCOPED_TRACE(sc.name);
    const Light l = spotLight(sc, seed++);
    const CookieImage& im = *l.cookie->images[0];
    for (int k = 0; k < 600; ++k) {
      // Inside the square [0, 1]^2 for the first third, then outside it (clamp to edge).
      const double lo = k < 200 ? 0.0 : -1.5, hi = k < 200 ? 1.0 : 2.5;
      const double u = rng.uniform(lo, hi), v = rng.uniform(lo, hi);
      const Vec3 p = spotPoint(l, u, v, rng.uniform(0.05, 12));
      const ref::SpotUV want = ref::spotUV(l, p);
      ASSERT_FALSE(want.behind);
      const lighting::CookieCoordinates got = lighting::cookieCoordinates(l, p);
      EXPECT_FALSE(got.outside) << at(p);
      EXPECT_TRUE(close(got.u, want.u)) << at(p);  // not clamped
      EXPECT_TRUE(close(got.v, want.v)) << at(p);
      const double value = lighting::cookieValue(l, p);
      const double mine = ref::spotValue(l, p);
      EXPECT_TRUE(close(value, mine)) << at(p) << " uv (" << u << ", " << v << ")";
      diff.note(value, mine);
    }
    // Clamp to edge by hand: beyond the last column on a row centre, the value is
    // that edge texel; beyond a corner, the corner texel; half-way between two
    // rows beyond the first column, the mean of the two edge texels.
    for (double far : {1.0 + 0.5 / sc.W, 1.7, 40.0}) {
      for (int j = 0; j < sc.H; ++j) {
        const Vec3 p = spotPoint(l, far, (j + 0.5) / sc.H, 1.5);
        EXPECT_TRUE(close(lighting::cookieValue(l, p), ref::texel(im, sc.W - 1, j))) << at(p);
        const Vec3 q = spotPoint(l, (j % sc.W + 0.5) / sc.W, 1 - far, 1.5);
        EXPECT_TRUE(close(lighting::cookieValue(l, q), ref::texel(im, j % sc.W, 0))) << at(q);
      }
      const Vec3 c = spotPoint(l, 1 - far, far, 0.8);
      EXPECT_TRUE(close(lighting::cookieValue(l, c), ref::texel(im, 0, sc.H - 1))) << at(c);
      const Vec3 m = spotPoint(l, 1 - far, 1.0 / sc.H, 0.8);
      EXPECT_TRUE(close(lighting::cookieValue(l, m), 0.5 * (ref::texel(im, 0, 0) + ref::texel(im, 0, 1)))) << at(m);
    }
    // Just in front of the apex plane (q.z = 1e-3), a metre to the side: far
    // outside the cone, the clamped edge of the image (not 0).
    const ref::Basis b = ref::basis(l.direction);
    for (double sx : {-1.0, 1.0})
      for (double sy : {-1.0, 0.0, 1.0}) {
        const Vec3 p = l.position + sx * b.r + sy * 0.5 * b.u + 1e-3 * b.f;
        const double value = lighting::cookieValue(l, p);
        const double mine = ref::spotValue(l, p);
        EXPECT_TRUE(close(value, mine)) << at(p);
        EXPECT_GT(value, 0.05) << at(p);
        diff.note(value, mine);
      }
  }
}

TEST(CookieIndependent, SpotIsExactlyZeroBehindTheApex) {
  Rng rng;
  int seed = 50;
  for (const SpotCase& sc : kSpot) {
    SCOPED_TRACE(sc.name);
    const Light l = spotLight(sc, seed++);
    const ref::Basis b = ref::basis(l.direction);
    for (int k = 0; k < 300; ++k) {
      const double z = -rng.uniform(1e-6, 10) * (k % 10 == 0 ? 1e-3 : 1.0);
      const Vec3 p = l.position + rng.uniform(-5, 5) * b.r + rng.uniform(-5, 5) * b.u + z * b.f;
      ASSERT_TRUE(ref::spotUV(l, p).behind) << at(p);
      EXPECT_EQ(lighting::cookieValue(l, p), 0.0) << at(p);
      EXPECT_TRUE(lighting::cookieCoordinates(l, p).outside) << at(p);
    }
    EXPECT_EQ(lighting::cookieValue(l, l.position), 0.0);  // the apex itself: q.z = 0
    EXPECT_TRUE(lighting::cookieCoordinates(l, l.position).outside);
  }
  // q.z exactly 0 away from the apex: a light along +X (f = (1, 0, 0), r = (0, 0, 1),
  // u = (0, 1, 0), all exact), points in the plane x = position.x.
  Light l = makeLight(LightType::Spot, {2, 1, -3}, {1, 0, 0}, {makeImage(4, 4, 59)});
  l.spotAngleDeg = 60;
  for (const Vec3& p : {Vec3(2, 1.5, -3), Vec3(2, -4, 7.25), Vec3(2, 1, 0.125), Vec3(2, 100, -300)}) {
    EXPECT_EQ(ref::dot(ref::sub(p, l.position), ref::basis(l.direction).f), 0.0) << "self-check " << at(p);
    EXPECT_EQ(lighting::cookieValue(l, p), 0.0) << at(p);
    EXPECT_TRUE(lighting::cookieCoordinates(l, p).outside) << at(p);
  }
  // And just in front of that plane the value is not 0 (it is the clamped edge).
  EXPECT_GT(lighting::cookieValue(l, Vec3(2.001, 1.5, -3)), 0.05);
  EXPECT_FALSE(lighting::cookieCoordinates(l, Vec3(2.001, 1.5, -3)).outside);
}

// ---------------------------------------------------------------------------
// Point: a cube of six faces, +X, -X, +Y, -Y, +Z, -Z.
// ---------------------------------------------------------------------------
constexpr int kCube = 6;

Light pointLight() {
  std::vector<std::shared_ptr<const CookieImage>> faces;
  for (int f = 0; f < 6; ++f) faces.push_back(makeImage(kCube, kCube, 60 + f));
  Light l = makeLight(LightType::Point, {-2.5, 1.75, 4.0}, {0, -1, 0}, faces);
  l.range = 7;
  return l;
}

const char* kFaceName[6] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};

TEST(CookieIndependent, PointFaceSelectionOnAllSixFaces) {
  const Light l = pointLight();
  // Hand-picked directions and the face and (u, v) the table gives them
  // (u = (sc/|ma| + 1)/2, v = (tc/|ma| + 1)/2), worked out by hand here.
  struct Case {
    Vec3 d;
    int face;
    double u, v;
  };
  const Case cases[] = {
      {{2, 0, 0}, 0, 0.5, 0.5},          {{4, 1, -2}, 0, 0.75, 0.375},    // +X: sc = -z, tc = -y
      {{1, 0.999, -0.998}, 0, 0.999, 0.0005},
      {{-2, 0, 0}, 1, 0.5, 0.5},         {{-4, 1, -2}, 1, 0.25, 0.375},   // -X: sc = +z, tc = -y
      {{-1, -0.5, 0.999}, 1, 0.9995, 0.75},
      {{0, 3, 0}, 2, 0.5, 0.5},          {{1, 4, -2}, 2, 0.625, 0.25},    // +Y: sc = +x, tc = +z
      {{-0.999, 1, 0.25}, 2, 0.0005, 0.625},
      {{0, -3, 0}, 3, 0.5, 0.5},         {{1, -4, -2}, 3, 0.625, 0.75},   // -Y: sc = +x, tc = -z
      {{0.5, -1, 0.999}, 3, 0.75, 0.0005},
      {{0, 0, 5}, 4, 0.5, 0.5},          {{1, -2, 4}, 4, 0.625, 0.75},    // +Z: sc = +x, tc = -y
      {{-0.999, 0.999, 1}, 4, 0.0005, 0.0005},
      {{0, 0, -5}, 5, 0.5, 0.5},         {{1, -2, -4}, 5, 0.375, 0.75},   // -Z: sc = -x, tc = -y
      {{0.999, -0.999, -1}, 5, 0.0005, 0.9995},
  };
  for (const Case& c : cases) {
    const ref::FaceUV mine = ref::cubeFace(c.d);
    EXPECT_EQ(mine.face, c.face) << "self-check " << at(c.d);
    EXPECT_TRUE(close(mine.u, c.u)) << "self-check " << at(c.d);
    EXPECT_TRUE(close(mine.v, c.v)) << "self-check " << at(c.d);
    const Vec3 p = l.position + c.d;
    const lighting::CookieCoordinates got = lighting::cookieCoordinates(l, p);
    EXPECT_FALSE(got.outside) << at(c.d);
    EXPECT_EQ(got.face, c.face) << "direction " << at(c.d) << " should pick " << kFaceName[c.face];
    EXPECT_TRUE(close(got.u, c.u)) << kFaceName[c.face] << " direction " << at(c.d);
    EXPECT_TRUE(close(got.v, c.v)) << kFaceName[c.face] << " direction " << at(c.d);
  }
  // Many directions per face, from the inverse of the table, at random lengths.
  Rng rng;
  for (int face = 0; face < 6; ++face)
    for (int k = 0; k < 200; ++k) {
      const double u = rng.uniform(0.001, 0.999), v = rng.uniform(0.001, 0.999);
      const Vec3 d = rng.uniform(0.05, 30) * ref::cubeDirection(face, u, v);
      const Vec3 p = l.position + d;
      const ref::FaceUV mine = ref::pointUV(l, p);
      ASSERT_EQ(mine.face, face) << "self-check " << at(d);
      const lighting::CookieCoordinates got = lighting::cookieCoordinates(l, p);
      EXPECT_EQ(got.face, face) << "direction " << at(d) << " should pick " << kFaceName[face];
      EXPECT_TRUE(close(got.u, mine.u)) << kFaceName[face] << " " << at(d);
      EXPECT_TRUE(close(got.v, mine.v)) << kFaceName[face] << " " << at(d);
    }
}

TEST(CookieIndependent, PointTexelCentresOnEveryFace) {
  Diff diff{"point texel centres"};
  const Light l = pointLight();
  for (int face = 0; face < 6; ++face) {
    SCOPED_TRACE(kFaceName[face]);
    const CookieImage& im = *l.cookie->images[std::size_t(face)];
    for (double length : {0.1, 1.0, 3.7, 50.0})
      for (int j = 0; j < kCube; ++j)
        for (int i = 0; i < kCube; ++i) {
          const Vec3 d = length * ref::cubeDirection(face, (i + 0.5) / kCube, (j + 0.5) / kCube);
          const Vec3 p = l.position + d;
          const ref::FaceUV mine = ref::pointUV(l, p);
          ASSERT_EQ(mine.face, face) << "self-check " << at(d);
          const lighting::CookieCoordinates got = lighting::cookieCoordinates(l, p);
          EXPECT_EQ(got.face, face) << at(d);
          EXPECT_TRUE(close(got.u, mine.u)) << at(d);
          EXPECT_TRUE(close(got.v, mine.v)) << at(d);
          const double value = lighting::cookieValue(l, p);
          const double want = ref::pointValue(l, p);
          EXPECT_TRUE(close(value, want)) << at(d) << " texel " << i << "," << j;
          EXPECT_TRUE(close(value, ref::texel(im, i, j))) << at(d) << " texel " << i << "," << j;
          diff.note(value, want);
        }
  }
}

TEST(CookieIndependent, PointInteriorBilinearOnEveryFace) {
  Diff diff{"point interior bilinear"};
  const Light l = pointLight();
  Rng rng;
  // At least one texel inside every face edge: u, v in [1/N, 1 - 1/N], so the
  // four taps (x = u N - 0.5 in [0.5, N - 1.5]) all lie on the face.
  const double lo = 1.0 / kCube, hi = 1.0 - 1.0 / kCube;
  for (int face = 0; face < 6; ++face) {
    SCOPED_TRACE(kFaceName[face]);
    const CookieImage& im = *l.cookie->images[std::size_t(face)];
    for (int k = 0; k < 400; ++k) {
      const double u = rng.uniform(lo, hi), v = rng.uniform(lo, hi);
      const Vec3 d = rng.uniform(0.05, 30) * ref::cubeDirection(face, u, v);
      const Vec3 p = l.position + d;
      const double value = lighting::cookieValue(l, p);
      const double want = ref::pointValue(l, p);
      EXPECT_TRUE(close(value, want)) << at(d) << " uv (" << u << ", " << v << ")";
      diff.note(value, want);
    }
    // By hand: the midpoint of four texels (1,2), (2,2), (1,3), (2,3) is their mean.
    const Vec3 d = 2.5 * ref::cubeDirection(face, 2.0 / kCube, 3.0 / kCube);
    const double mean =
        0.25 * (ref::texel(im, 1, 2) + ref::texel(im, 2, 2) + ref::texel(im, 1, 3) + ref::texel(im, 2, 3));
    EXPECT_TRUE(close(lighting::cookieValue(l, l.position + d), mean)) << at(d);
  }
}

}  // namespace
