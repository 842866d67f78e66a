// An independent double-precision evaluation of SPEC sections 1 and 3 (3.1-3.4
// and the specular BRDF of 3.8) on plane scenes, shared by the tests that check
// the CPU reference (SPEC 6) and the rendering backends against it.
//
// Independence is the point: nothing here calls the project's light math,
// camera, transform, mesh, light evaluation or BVH. The camera rays, the
// ray-plane intersection, the legacy triangulation and barycentrics, and every
// formula of SPEC 3.1-3.4 and 3.8 are written out again from the text, and the
// lights that reach the plane (SPEC 4 and 5) are chosen by hand per scene and
// written down beside each scene builder. The only project code used is the scene
// loader, prepareScene/prepareFrame and, for the reference comparison, the
// reference renderer under test.
//
// Each scene is described once, as a SceneSpec; the same description is
// written out as SPEC 2 JSON for the project's loader and evaluated here.
#pragma once

#include "reference/reference_renderer.h"

#include <glm/vec3.hpp>

#include <optional>
#include <string>
#include <vector>

namespace independent_plane {

using Vec = glm::dvec3;

// ---------------------------------------------------------------------------
// Scene descriptions (the subset of SPEC 2 these tests need)

struct CameraSpec {
  bool perspective = false;
  Vec position{0, 10, 0};
  Vec target{0, 0, 0};
  Vec up{0, 0, -1};
  double fovYDeg = 60;       // perspective
  double orthoHeight = 10;   // orthographic
  double nearPlane = 0.1;
  double farPlane = 100;
};

// SPEC 2 `material.brdf: srp` (SPEC 3.8): metallic and smoothness in [0, 1].
struct SrpMaterial {
  double metallic = 0;
  double smoothness = 0.5;
};

// An unrotated plane of scale 1: the surface y = centre.y, normal +Y.
struct PlaneSpec {
  Vec centre{0, 0, 0};
  double sizeX = 10, sizeZ = 10;
  int subdivisions = 1;
  Vec albedo{1, 1, 1};
  // Absent: `lambert` (SPEC 3.1-3.2 as written; nothing about the BRDF is
  // written into the JSON). Present: `"brdf": "srp"` with its metallic and
  // smoothness, evaluated by SPEC 3.8.
  std::optional<SrpMaterial> srp;
};

enum class Kind { Directional, Point, Spot };

struct LightSpec {
  std::string name;
  Kind kind = Kind::Point;
  Vec position{0, 0, 0};
  Vec direction{0, -1, 0};  // the way the light travels (not normalised here)
  double range = 1;
  double outerDeg = 60;            // spot_angle_deg, the full outer cone
  std::optional<double> innerDeg;  // inner_spot_angle_deg; absent: SPEC 3.4
  Vec color{1, 1, 1};
  double intensity = 1;
};

struct SceneSpec {
  std::string name;
  int width = 32, height = 32;
  CameraSpec camera;
  std::string profile = "srp";
  bool lightsPerObject = false;
  Vec ambient{0, 0, 0};
  PlaneSpec plane;
  std::vector<LightSpec> lights;
};

// The lights that shade the plane, by name, as chosen by hand (SPEC 4 and 5).
struct AppliedLights {
  std::vector<std::string> perPixel;
  std::vector<std::string> perVertex;
};

// A scene together with the lights that reach its plane.
struct PlaneCase {
  SceneSpec scene;
  AppliedLights applied;
};

// SPEC 2 JSON for the scene; 17 significant digits so every double survives.
std::string sceneJson(const SceneSpec& s);

// The index of the light called `name` (a test failure and -1 when absent).
int lightIndex(const SceneSpec& s, const std::string& name);
std::vector<std::string> allLightNames(const SceneSpec& s);

// ---------------------------------------------------------------------------
// SPEC 1: camera rays through pixel centres, and what they hit

double radians(double degrees);
double saturate(double x);
double square(double x);
double luminance(const Vec& c);

struct CameraRay {
  Vec origin;
  Vec direction;  // unit
};

// The ray through the point (x, y) of the image in pixel units (column x from
// the left, row y from the top); the centre of pixel (i, j) is (i + 0.5, j + 0.5).
CameraRay imageRay(const SceneSpec& s, double x, double y);
// The ray through the centre of pixel (i, j).
CameraRay pixelRay(const SceneSpec& s, int i, int j);

// The point a ray sees on the plane, if any: y = centre.y, seen from above (the
// only front face of an unrotated plane), within the plane's extent and
// between the near and far planes.
std::optional<Vec> hitPlane(const SceneSpec& s, const CameraRay& ray);

// Pixel centres closer than this (in pixels, screen space) to the edge of the
// plane's image may land on either side of it in a rasteriser: Vulkan keeps
// subPixelPrecisionBits (at least 4) fractional bits of each vertex's x and y
// and says nothing of the rounding, so each vertex may move by up to 1/16
// pixel on each axis, on its own, and an edge by up to sqrt(2)/16; this is
// twice 1/16, the distance SPEC 6's reference masks on a 4-bit device
// (reference/tolerance_model.h edgeDistancePx). It is written out again here
// so this model stays independent of the reference.
constexpr double kEdgeDistancePx = 1.0 / 8.0;

// Whether the disc of radius kEdgeDistancePx around the centre of pixel (i, j)
// holds points on both sides of the plane's edge in the image (the silhouette
// of the plane or the near/far clipping planes): some point of it hits the
// plane and some other does not. Tested at the centre and at 16 points of a
// circle of radius kEdgeDistancePx / cos(pi/16), which encloses the disc, so
// a straight edge within kEdgeDistancePx is never missed (a few pixels a
// little farther may be flagged too).
bool nearPlaneEdge(const SceneSpec& s, int i, int j);

// ---------------------------------------------------------------------------
// SPEC 3.1-3.4, straight from the text (shadowMask = 1: no mixed lights here)

// SPEC 3.4: cos of the legacy inner half-angle for a full outer cone `outerDeg`.
double legacyCosInner(double outerDeg);

// finalColor * saturate(dot(N, L)) * attenuation of one light at p, without
// the albedo. `legacyInnerAlways`: the legacy profile's inner angle (SPEC 4).
Vec lightTerm(const LightSpec& l, const Vec& p, const Vec& N, bool legacyInnerAlways);

// The sum of lightTerm over `lights` (scene indices).
Vec sumLights(const SceneSpec& s, const std::vector<int>& lights, const Vec& p, const Vec& N);

// SPEC 3.8, written again from the text (see the .cpp for each line).

// L of SPEC 3.1 (directional: -direction, normalised) or 3.2 (point, spot:
// ray * inversesqrt(max(dot(ray, ray), 1e-5)), 0 when p == position).
Vec lightDirection(const LightSpec& l, const Vec& p);

// V of SPEC 3.8: perspective normalize(cameraPosition - p); orthographic the
// unit vector opposite the view direction, normalize(position - target).
Vec viewVector(const SceneSpec& s, const Vec& p);

// Every intermediate of SPEC 3.8 for one material, albedo, N, L and V.
struct SrpBrdf {
  double oneMinusReflectivity = 0;
  Vec diffuse{0.0};
  Vec F0{0.0};
  double roughness = 0;
  Vec H{0.0};
  double nh2 = 0, lh2 = 0, r2 = 0, d2 = 0;
  double specularStrength = 0;
  Vec directBRDF{0.0};  // specularStrength * F0 + diffuse
};
SrpBrdf srpBrdf(const SrpMaterial& m, const Vec& albedo, const Vec& N, const Vec& L, const Vec& V);

// SPEC 3.8: diffuse = A * 0.96 * (1 - metallic), the factor of the ambient term.
Vec srpDiffuse(const SrpMaterial& m, const Vec& albedo);

// SPEC 2 plane triangulation and SPEC 4 vertex lights: the lights are
// evaluated at the three corners of the triangle holding p (normal +Y) and
// interpolated with p's barycentrics. One entry per light of `lights`.
std::vector<Vec> vertexLightTerms(const SceneSpec& s, const std::vector<int>& lights, const Vec& p);
// Their sum.
Vec vertexLights(const SceneSpec& s, const std::vector<int>& lights, const Vec& p);

// What the model says about one pixel.
struct ExpectedPixel {
  bool onPlane = false;   // the ray through the pixel centre hits the plane
  bool nearEdge = false;  // nearPlaneEdge: either side is a correct result
  Vec value{0.0};         // SPEC 3 colour; 0 for background
  // The largest channel of the largest single light's contribution
  // albedo * lightTerm (per-pixel or interpolated vertex light); 0 off the plane.
  double largestLightContribution = 0;
  // srp only (SPEC 3.8): the sum over the lights of the specular part,
  // lightTerm * specularStrength * F0 (the rest of the value is diffuse * (ambient
  // + sum of lightTerm)); 0 for lambert and off the plane.
  Vec specular{0.0};
};

// Row-major, row 0 at the top, width * height entries. With an offset, each
// pixel's value is the one seen through its centre moved by (offsetX,
// offsetY) pixels (onPlane likewise; nearEdge stays the centre's).
std::vector<ExpectedPixel> expectedPixels(const SceneSpec& s, const AppliedLights& applied, double offsetX = 0,
                                          double offsetY = 0);

// SPEC 3: colour = A * ambient + A * (sum of the lights); no lightmap here.
// srp (SPEC 3.8): colour = diffuse * ambient + sum of lightTerm * directBRDF,
// per-pixel lights only (srp is an error in the legacy profile, the only one
// with vertex lights). Row-major values of expectedPixels.
std::vector<Vec> expectedImage(const SceneSpec& s, const AppliedLights& applied);

// ---------------------------------------------------------------------------
// Light and scene builders

LightSpec point(std::string name, Vec position, double range, double intensity, Vec color = Vec(1.0));
LightSpec spot(std::string name, Vec position, Vec direction, double range, double outerDeg,
               std::optional<double> innerDeg, double intensity, Vec color = Vec(1.0));
LightSpec directional(std::string name, Vec direction, double intensity, Vec color = Vec(1.0));

// Case 1: orthographic, straight down, 64x48 (16 x 12 world units) over a
// 10x10 plane, so background on every side. srp without per-object lists: all
// four lights are kept (1 directional of 4, 3 others of 64) and applied per
// pixel. One spot has an inner angle, one uses the legacy rule (3.4), and the
// directional light grazes at 89 degrees from the normal.
PlaneCase orthographicCase();

// Case 2: a perspective view over a plane lit by point and spot lights (srp,
// no per-object lists, far fewer than 64 lights and no directional light: every
// light is kept and applied per pixel; a light outside the frustum could not
// reach a visible point anyway). The plane ends at z = -20 inside the view, so
// the top rows show background. Everything is moved by `offset`.
SceneSpec perspectiveScene(const Vec& offset);
PlaneCase perspectiveCase();
// Case 3: the whole of case 2 moved by 1e5 in x and z (SPEC 10 `stability`).
PlaneCase perspectiveFarCase();

// Case 4: orthographic straight down, 32x32 over 8x8 world units, so pixel
// centres sit at odd multiples of 0.125. "p_on" lies on the plane at the centre
// of pixel (16, 16): dot(N, L) = 0 everywhere and L = 0 where p == position, so
// its term is 0. "p_low" is 0.003 above the centre of pixel (8, 20): there
// distSqr = 9e-6 is clamped to 1e-5 (3.2) and |L| = 0.003 / sqrt(1e-5).
// Its intensity is small so that its peak does not dwarf "p_main".
PlaneCase lightOnSurfaceCase();

// Cases 5 and 7: eleven white point lights (luminance = intensity), all on a
// circle of radius 3 at height 1 around the plane's centre, so d^2 = 10 to the
// plane's bounding-sphere centre for every one and, with equal ranges, SPEC 5.2
// importance is proportional to intensity. srp with per-object lists.
SceneSpec elevenLightsScene();
// Case 5: all 11 lights touch the plane's bounding sphere (centre (0,0,0),
// radius sqrt(50) = 7.07; d = sqrt(10) = 3.16 <= 8 + 7.07). Intensities by
// scene index: p0 2.0, p1 0.6, p2 3.2, p3 1.4, p4 0.3, p5 2.6, p6 1.0, p7 3.8,
// p8 0.45, p9 2.3, p10 1.7. SPEC 5.2 order (importance proportional to
// intensity): p7, p2, p5, p9, p0, p10, p3, p6 | p1, p8, p4. The first 8 are
// applied per pixel; p1, p8 and p4 are not.
PlaneCase perObjectTruncationCase();
// Case 7: the scene of case 5 as --ideal (SPEC 6) sees it: all 11 per pixel.
PlaneCase idealEveryLightCase();

// Case 6: legacy profile. List order (SPEC 5.2): the directional "d0" first,
// then the point and spot lights by importance; all seven sit on a circle of
// radius 3 at height 1.2 (d^2 = 10.44, equal ranges) with white colour, so by
// intensity: s2 4.0, p5 3.0, s4 2.2, p1 1.5, p6 1.1, p3 0.8, s7 0.6.
// Positions 0-3 per pixel: d0, s2, p5, s4. Positions 4-7 per vertex: p1, p6,
// p3, s7. Every spot uses the legacy inner rule, also s2 and s7 whose scene
// gives an inner angle (SPEC 4).
PlaneCase legacyVertexLightsCase();

// ---------------------------------------------------------------------------
// The reference renderer (SPEC 6) against the model, to 1e-6 relative

// keepExactValues: also fill ReferenceImages::exactValue (the double colour).
reference::ReferenceImages renderReference(const SceneSpec& s, bool ideal, bool keepExactValues = false);

struct ComparisonResult {
  double maxRelative = 0;  // largest |reference - expected| / max(|expected|, floor)
  int compared = 0;
  int lit = 0;  // compared pixels where the plane is hit
};

// Compares every pixel the reference's mask keeps (A = 1) with `expected` to
// 1e-6 relative, floored at 1e-3 of the image's largest value; checks that
// values and tolerances are finite and masks 0 or 1, and that fewer than 5% of
// the pixels are masked. Reports through gtest failures.
ComparisonResult compareWithExpected(const SceneSpec& s, const reference::ReferenceImages& images,
                                     const std::vector<Vec>& expected);

// Renders the scene with the reference, evaluates it here with the lights
// `applied`, compares.
ComparisonResult checkScene(const SceneSpec& s, const AppliedLights& applied, bool ideal = false);

// ---------------------------------------------------------------------------
// The reference's double values (ReferenceImages::exactValue, rendered with
// keepExactValues) against the model, to 1e-9 relative

// Compares, in double, every pixel the reference's mask keeps (A = 1 in
// images.value) with `expected` to 1e-9 relative, floored at 1e-7 of the image's
// largest value (see the .cpp for why); checks that exactValue has one finite
// entry per pixel and that fewer than 5% of the pixels are masked. Reports
// through gtest failures.
ComparisonResult compareExact(const SceneSpec& s, const reference::ReferenceImages& images,
                              const std::vector<Vec>& expected);

// Renders the scene with the reference (keepExactValues), evaluates it here
// with the lights `applied`, compares with compareExact.
ComparisonResult checkSceneExact(const SceneSpec& s, const AppliedLights& applied);

}  // namespace independent_plane
