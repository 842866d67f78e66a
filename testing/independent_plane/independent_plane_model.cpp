// The independent plane model; see independent_plane_model.h for what it may
// and may not use from the project.
#include "testing/independent_plane/independent_plane_model.h"

#include "lighting/frame.h"
#include "scene_input/scene_loader.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <numbers>
#include <sstream>

namespace independent_plane {

// ---------------------------------------------------------------------------
// Scene descriptions

namespace {

std::string jsonVec(const Vec& v) {
  std::ostringstream out;
  out << std::setprecision(17) << '[' << v.x << ", " << v.y << ", " << v.z << ']';
  return out.str();
}

}  // namespace

std::string sceneJson(const SceneSpec& s) {
  std::ostringstream out;
  out << std::setprecision(17);
  out << "{\n  \"lightcts\": 1,\n  \"name\": \"" << s.name << "\",\n";
  out << "  \"image\": {\"width\": " << s.width << ", \"height\": " << s.height << "},\n";
  const CameraSpec& c = s.camera;
  out << "  \"camera\": {\"position\": " << jsonVec(c.position) << ", \"target\": " << jsonVec(c.target)
      << ", \"up\": " << jsonVec(c.up) << ", ";
  if (c.perspective)
    out << "\"projection\": \"perspective\", \"fov_y_deg\": " << c.fovYDeg;
  else
    out << "\"projection\": \"orthographic\", \"height\": " << c.orthoHeight;
  out << ", \"near\": " << c.nearPlane << ", \"far\": " << c.farPlane << "},\n";
  out << "  \"pipeline\": {\"profile\": \"" << s.profile << "\", \"path\": \"forward\", \"lights_per_object\": "
      << (s.lightsPerObject ? "true" : "false") << "},\n";
  out << "  \"ambient\": " << jsonVec(s.ambient) << ",\n";
  const PlaneSpec& p = s.plane;
  out << "  \"objects\": [{\"name\": \"plane\", \"mesh\": {\"type\": \"plane\", \"size\": [" << p.sizeX << ", "
      << p.sizeZ << "], \"subdivisions\": " << p.subdivisions << "}, \"transform\": {\"translate\": "
      << jsonVec(p.centre) << ", \"rotate_deg\": [0, 0, 0], \"scale\": 1}, \"material\": {\"albedo\": "
      << jsonVec(p.albedo);
  if (p.srp)
    out << ", \"brdf\": \"srp\", \"metallic\": " << p.srp->metallic << ", \"smoothness\": " << p.srp->smoothness;
  out << "}}],\n";
  out << "  \"lights\": [";
  for (std::size_t k = 0; k < s.lights.size(); ++k) {
    const LightSpec& l = s.lights[k];
    out << (k ? ",\n    " : "\n    ") << "{\"name\": \"" << l.name << "\", ";
    switch (l.kind) {
      case Kind::Directional: out << "\"type\": \"directional\", \"direction\": " << jsonVec(l.direction); break;
      case Kind::Point: out << "\"type\": \"point\", \"position\": " << jsonVec(l.position) << ", \"range\": " << l.range; break;
      case Kind::Spot:
        out << "\"type\": \"spot\", \"position\": " << jsonVec(l.position) << ", \"direction\": "
            << jsonVec(l.direction) << ", \"range\": " << l.range << ", \"spot_angle_deg\": " << l.outerDeg;
        if (l.innerDeg) out << ", \"inner_spot_angle_deg\": " << *l.innerDeg;
        break;
    }
    out << ", \"color\": " << jsonVec(l.color) << ", \"intensity\": " << l.intensity << ", \"mode\": \"realtime\"}";
  }
  out << "\n  ]\n}\n";
  return out.str();
}

int lightIndex(const SceneSpec& s, const std::string& name) {
  for (int k = 0; k < int(s.lights.size()); ++k)
    if (s.lights[k].name == name) return k;
  ADD_FAILURE() << "no light named " << name;
  return -1;
}

std::vector<std::string> allLightNames(const SceneSpec& s) {
  std::vector<std::string> names;
  for (const LightSpec& l : s.lights) names.push_back(l.name);
  return names;
}

// ---------------------------------------------------------------------------
// SPEC 1: camera rays through pixel centres

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }
double saturate(double x) { return std::clamp(x, 0.0, 1.0); }
double square(double x) { return x * x; }
double luminance(const Vec& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

namespace {

struct CameraBasis {
  Vec forward, right, up;
};

// lookAt: the view looks along `forward` (view-space -Z), right = forward x up.
CameraBasis lookAtBasis(const CameraSpec& c) {
  CameraBasis b;
  b.forward = glm::normalize(c.target - c.position);
  b.right = glm::normalize(glm::cross(b.forward, c.up));
  b.up = glm::cross(b.right, b.forward);
  return b;
}

}  // namespace

CameraRay imageRay(const SceneSpec& s, double px, double py) {
  const CameraSpec& c = s.camera;
  const CameraBasis b = lookAtBasis(c);
  const double aspect = double(s.width) / double(s.height);
  const double x = 2.0 * px / s.width - 1.0;  // NDC
  const double y = 1.0 - 2.0 * py / s.height;
  if (c.perspective) {
    const double tanHalf = std::tan(radians(c.fovYDeg) / 2.0);
    return {c.position, glm::normalize(b.forward + (x * tanHalf * aspect) * b.right + (y * tanHalf) * b.up)};
  }
  const double halfHeight = c.orthoHeight / 2.0;
  return {c.position + (x * halfHeight * aspect) * b.right + (y * halfHeight) * b.up, b.forward};
}

CameraRay pixelRay(const SceneSpec& s, int i, int j) { return imageRay(s, i + 0.5, j + 0.5); }

std::optional<Vec> hitPlane(const SceneSpec& s, const CameraRay& ray) {
  const PlaneSpec& p = s.plane;
  if (!(ray.direction.y < 0.0) || !(ray.origin.y > p.centre.y)) return std::nullopt;
  const double t = (p.centre.y - ray.origin.y) / ray.direction.y;
  Vec hit = ray.origin + t * ray.direction;
  hit.y = p.centre.y;  // exactly on the plane, as the mesh vertices are
  if (std::abs(hit.x - p.centre.x) > p.sizeX / 2 || std::abs(hit.z - p.centre.z) > p.sizeZ / 2) return std::nullopt;
  const double depth = t * glm::dot(ray.direction, lookAtBasis(s.camera).forward);
  if (depth < s.camera.nearPlane || depth > s.camera.farPlane) return std::nullopt;
  return hit;
}

bool nearPlaneEdge(const SceneSpec& s, int i, int j) {
  constexpr int kDirections = 16;
  const double radius = kEdgeDistancePx / std::cos(std::numbers::pi / kDirections);
  const bool centre = hitPlane(s, pixelRay(s, i, j)).has_value();
  for (int k = 0; k < kDirections; ++k) {
    const double angle = 2.0 * std::numbers::pi * k / kDirections;
    const double x = i + 0.5 + radius * std::cos(angle), y = j + 0.5 + radius * std::sin(angle);
    if (hitPlane(s, imageRay(s, x, y)).has_value() != centre) return true;
  }
  return false;
}

// ---------------------------------------------------------------------------
// SPEC 3.1-3.4, straight from the text (shadowMask = 1: no mixed lights here)

// SPEC 3.4: tan(ri) = (46/64) tan(ro); ro = 90 degrees gives ri = 90 degrees.
double legacyCosInner(double outerDeg) {
  const double ro = radians(outerDeg / 2.0);
  if (outerDeg >= 180.0) return std::cos(std::numbers::pi / 2.0);
  return std::cos(std::atan((46.0 / 64.0) * std::tan(ro)));
}

Vec lightTerm(const LightSpec& l, const Vec& p, const Vec& N, bool legacyInnerAlways) {
  const Vec finalColor = l.color * l.intensity;
  if (l.kind == Kind::Directional) {  // 3.1
    const Vec L = -glm::normalize(l.direction);
    return finalColor * saturate(glm::dot(N, L));
  }
  // 3.2
  const Vec ray = l.position - p;
  const double distSqr = std::max(glm::dot(ray, ray), 1e-5);
  const Vec L = ray * (1.0 / std::sqrt(distSqr));
  const double invRangeSq = 1.0 / std::max(l.range * l.range, 1e-5);
  const double rangeAtt = square(saturate(1.0 - square(distSqr * invRangeSq)));
  double spotAtt = 1.0;  // point: a = 0, b = 1
  if (l.kind == Kind::Spot) {
    // 3.3, with 3.4 when the inner angle is absent or the profile is legacy (4).
    const Vec spotDir = -glm::normalize(l.direction);
    const double cosOuter = std::cos(radians(l.outerDeg / 2.0));
    const double cosInner =
        (l.innerDeg && !legacyInnerAlways) ? std::cos(radians(*l.innerDeg / 2.0)) : legacyCosInner(l.outerDeg);
    const double a = 1.0 / std::max(cosInner - cosOuter, 0.001);
    const double b = -cosOuter * a;
    spotAtt = square(saturate(glm::dot(spotDir, L) * a + b));
  }
  const double attenuation = spotAtt * rangeAtt / distSqr;
  return finalColor * saturate(glm::dot(N, L)) * attenuation;
}

Vec sumLights(const SceneSpec& s, const std::vector<int>& lights, const Vec& p, const Vec& N) {
  Vec sum(0.0);
  for (int k : lights) sum += lightTerm(s.lights[k], p, N, s.profile == "legacy");
  return sum;
}

// ---------------------------------------------------------------------------
// SPEC 3.8, line by line from the text

Vec lightDirection(const LightSpec& l, const Vec& p) {
  if (l.kind == Kind::Directional) return -glm::normalize(l.direction);  // 3.1: L = -direction
  // 3.2: L = ray * inversesqrt(distSqr), distSqr = max(dot(ray, ray), 1e-5)
  const Vec ray = l.position - p;
  const double distSqr = std::max(glm::dot(ray, ray), 1e-5);
  return ray * (1.0 / std::sqrt(distSqr));
}

Vec viewVector(const SceneSpec& s, const Vec& p) {
  const CameraSpec& c = s.camera;
  if (c.perspective) return glm::normalize(c.position - p);  // normalize(cameraPosition - p)
  // The view direction is normalize(target - position) (lookAt, SPEC 1).
  return -glm::normalize(c.target - c.position);
}

Vec srpDiffuse(const SrpMaterial& m, const Vec& albedo) {
  const double oneMinusReflectivity = 0.96 * (1.0 - m.metallic);  // MIN_REFLECTIVITY 0.04
  return albedo * oneMinusReflectivity;
}

SrpBrdf srpBrdf(const SrpMaterial& m, const Vec& albedo, const Vec& N, const Vec& L, const Vec& V) {
  SrpBrdf b;
  b.oneMinusReflectivity = 0.96 * (1.0 - m.metallic);
  b.diffuse = albedo * b.oneMinusReflectivity;
  // lerp(0.04, A, metallic) per channel: 0.04 + (A - 0.04) * metallic
  for (int c = 0; c < 3; ++c) b.F0[c] = 0.04 + (albedo[c] - 0.04) * m.metallic;
  b.roughness = square(1.0 - m.smoothness);
  // SafeNormalize: the floor is FLT_MIN (1.17549435e-38), so L = -V gives H = 0.
  const Vec sum = L + V;
  b.H = sum * (1.0 / std::sqrt(std::max(glm::dot(sum, sum), 1.17549435e-38)));
  b.nh2 = square(saturate(glm::dot(N, b.H)));
  b.lh2 = square(saturate(glm::dot(L, b.H)));
  b.r2 = square(b.roughness);
  b.d2 = square(b.nh2 * (b.r2 - 1.0) + 1.00001);
  b.specularStrength = b.r2 / (b.d2 * std::max(0.1, b.lh2) * (b.roughness * 4.0 + 2.0));
  b.directBRDF = b.specularStrength * b.F0 + b.diffuse;
  return b;
}

std::vector<Vec> vertexLightTerms(const SceneSpec& s, const std::vector<int>& lights, const Vec& p) {
  const PlaneSpec& plane = s.plane;
  const int n = plane.subdivisions;
  const auto vertexPosition = [&](int vi, int vj) {
    return plane.centre + Vec(-plane.sizeX / 2 + plane.sizeX * vi / n, 0.0, -plane.sizeZ / 2 + plane.sizeZ * vj / n);
  };
  // Grid coordinates: vertex (i, j) sits at (u, w) = (i, j).
  const double u = (p.x - plane.centre.x + plane.sizeX / 2) / plane.sizeX * n;
  const double w = (p.z - plane.centre.z + plane.sizeZ / 2) / plane.sizeZ * n;
  const int ci = std::clamp(int(std::floor(u)), 0, n - 1);
  const int cj = std::clamp(int(std::floor(w)), 0, n - 1);
  const double fu = u - ci, fw = w - cj;  // within the cell, v00 = (0,0), v10 = (1,0), v01 = (0,1), v11 = (1,1)
  struct Corner {
    int di, dj;
    double weight;
  };
  Corner corners[3];
  if (fw >= fu) {
    // Triangle (v00, v01, v11): (fu, fw) = b01 * (0,1) + b11 * (1,1).
    corners[0] = {0, 0, 1.0 - fw};
    corners[1] = {0, 1, fw - fu};
    corners[2] = {1, 1, fu};
  } else {
    // Triangle (v00, v11, v10): (fu, fw) = b11 * (1,1) + b10 * (1,0).
    corners[0] = {0, 0, 1.0 - fu};
    corners[1] = {1, 1, fw};
    corners[2] = {1, 0, fu - fw};
  }
  const Vec N(0, 1, 0);
  std::vector<Vec> terms;
  for (int k : lights) {
    Vec term(0.0);
    for (const Corner& c : corners)
      term += c.weight * lightTerm(s.lights[k], vertexPosition(ci + c.di, cj + c.dj), N, s.profile == "legacy");
    terms.push_back(term);
  }
  return terms;
}

Vec vertexLights(const SceneSpec& s, const std::vector<int>& lights, const Vec& p) {
  Vec sum(0.0);
  for (const Vec& term : vertexLightTerms(s, lights, p)) sum += term;
  return sum;
}

std::vector<ExpectedPixel> expectedPixels(const SceneSpec& s, const AppliedLights& applied, double offsetX,
                                          double offsetY) {
  std::vector<int> perPixel, perVertex;
  for (const std::string& name : applied.perPixel) perPixel.push_back(lightIndex(s, name));
  for (const std::string& name : applied.perVertex) perVertex.push_back(lightIndex(s, name));
  const Vec N(0, 1, 0);
  const Vec& albedo = s.plane.albedo;
  const auto largestChannel = [&](const Vec& term) {
    const Vec c = albedo * term;
    return std::max({std::abs(c.r), std::abs(c.g), std::abs(c.b)});
  };
  std::vector<ExpectedPixel> image(std::size_t(s.width) * s.height);
  for (int j = 0; j < s.height; ++j)
    for (int i = 0; i < s.width; ++i) {
      ExpectedPixel& pixel = image[std::size_t(j) * s.width + i];
      pixel.nearEdge = nearPlaneEdge(s, i, j);
      const std::optional<Vec> p = hitPlane(s, imageRay(s, i + 0.5 + offsetX, j + 0.5 + offsetY));
      if (!p) continue;  // background: 0
      pixel.onPlane = true;
      if (s.plane.srp) {
        // SPEC 3.8: sum of finalColor * saturate(dot(N, L)) * attenuation *
        // directBRDF, plus diffuse * ambient. No vertex lights (legacy only).
        EXPECT_TRUE(perVertex.empty()) << "srp materials have no vertex lights (SPEC 2: srp is an error in legacy)";
        const SrpMaterial& m = *s.plane.srp;
        const Vec V = viewVector(s, *p);
        Vec value = srpDiffuse(m, albedo) * s.ambient;
        for (int k : perPixel) {
          const LightSpec& l = s.lights[k];
          // finalColor * saturate(dot(N, L)) * attenuation
          const Vec term = lightTerm(l, *p, N, s.profile == "legacy");
          const SrpBrdf b = srpBrdf(m, albedo, N, lightDirection(l, *p), V);
          const Vec contribution = term * b.directBRDF;
          value += contribution;
          pixel.specular += term * (b.specularStrength * b.F0);
          pixel.largestLightContribution = std::max({pixel.largestLightContribution, std::abs(contribution.r),
                                                     std::abs(contribution.g), std::abs(contribution.b)});
        }
        pixel.value = value;
        continue;
      }
      Vec light(0.0);
      for (int k : perPixel) {
        const Vec term = lightTerm(s.lights[k], *p, N, s.profile == "legacy");
        light += term;
        pixel.largestLightContribution = std::max(pixel.largestLightContribution, largestChannel(term));
      }
      if (!perVertex.empty())
        for (const Vec& term : vertexLightTerms(s, perVertex, *p)) {
          light += term;
          pixel.largestLightContribution = std::max(pixel.largestLightContribution, largestChannel(term));
        }
      pixel.value = albedo * (s.ambient + light);
    }
  return image;
}

std::vector<Vec> expectedImage(const SceneSpec& s, const AppliedLights& applied) {
  std::vector<Vec> image;
  for (const ExpectedPixel& pixel : expectedPixels(s, applied)) image.push_back(pixel.value);
  return image;
}

// ---------------------------------------------------------------------------
// Light and scene builders

LightSpec point(std::string name, Vec position, double range, double intensity, Vec color) {
  LightSpec l;
  l.name = std::move(name);
  l.kind = Kind::Point;
  l.position = position;
  l.range = range;
  l.intensity = intensity;
  l.color = color;
  return l;
}

LightSpec spot(std::string name, Vec position, Vec direction, double range, double outerDeg,
               std::optional<double> innerDeg, double intensity, Vec color) {
  LightSpec l = point(std::move(name), position, range, intensity, color);
  l.kind = Kind::Spot;
  l.direction = direction;
  l.outerDeg = outerDeg;
  l.innerDeg = innerDeg;
  return l;
}

LightSpec directional(std::string name, Vec direction, double intensity, Vec color) {
  LightSpec l;
  l.name = std::move(name);
  l.kind = Kind::Directional;
  l.direction = direction;
  l.intensity = intensity;
  l.color = color;
  return l;
}

PlaneCase orthographicCase() {
  SceneSpec s;
  s.name = "independent-orthographic";
  s.width = 64;
  s.height = 48;
  s.camera.orthoHeight = 12;
  s.ambient = Vec(0.05, 0.04, 0.03);
  s.plane.albedo = Vec(0.8, 0.5, 0.25);
  const double grazing = radians(89);  // L at 89 degrees from the normal
  s.lights = {
      point("p0", Vec(-2.5, 1.5, 1.0), 6, 3.0, Vec(1.0, 0.9, 0.8)),
      spot("s_inner_outer", Vec(2.0, 2.0, -1.5), Vec(0.2, -1, 0.1), 7, 60, 30, 4.0, Vec(0.9, 1.0, 1.0)),
      spot("s_legacy_inner", Vec(1.0, 3.0, 2.5), Vec(-0.1, -1, -0.2), 8, 50, std::nullopt, 5.0),
      directional("d_grazing", Vec(-std::sin(grazing), -std::cos(grazing), 0), 2.0, Vec(1.0, 1.0, 0.9)),
  };
  return {s, {allLightNames(s), {}}};
}

SceneSpec perspectiveScene(const Vec& offset) {
  SceneSpec s;
  s.name = "independent-perspective";
  s.width = 64;
  s.height = 48;
  s.camera.perspective = true;
  s.camera.position = offset + Vec(3, 6, 8);
  s.camera.target = offset + Vec(0, 0, 0);
  s.camera.up = Vec(0, 1, 0);
  s.camera.fovYDeg = 50;
  s.ambient = Vec(0.02, 0.02, 0.03);
  s.plane.centre = offset;
  s.plane.sizeX = 40;
  s.plane.sizeZ = 40;
  s.plane.subdivisions = 3;
  s.plane.albedo = Vec(0.7, 0.65, 0.5);
  s.lights = {
      point("p0", offset + Vec(-1.5, 1.2, 0.5), 5, 2.5, Vec(1.0, 0.8, 0.6)),
      point("p1", offset + Vec(2.0, 0.7, -1.0), 3.5, 1.5, Vec(0.5, 0.8, 1.0)),
      point("p2", offset + Vec(0.3, 2.5, 2.5), 9, 6.0),
      spot("s0", offset + Vec(-0.5, 2.0, -2.0), Vec(0.3, -1, 0.2), 7, 60, 30, 5.0, Vec(1.0, 0.9, 0.7)),
      spot("s1", offset + Vec(2.5, 3.0, 1.0), Vec(-0.4, -1, -0.3), 8, 45, std::nullopt, 8.0),
      // inner == outer: cosInner - cosOuter = 0, so a = 1 / 0.001 (3.3)
      spot("s2", offset + Vec(-3.0, 1.5, 3.0), Vec(0.2, -1, -0.5), 6, 70, 70, 4.0, Vec(0.6, 1.0, 0.6)),
  };
  return s;
}

PlaneCase perspectiveCase() {
  const SceneSpec s = perspectiveScene(Vec(0.0));
  return {s, {allLightNames(s), {}}};
}

PlaneCase perspectiveFarCase() {
  SceneSpec s = perspectiveScene(Vec(1e5, 0, 1e5));
  s.name = "independent-perspective-far";
  return {s, {allLightNames(s), {}}};
}

PlaneCase lightOnSurfaceCase() {
  SceneSpec s;
  s.name = "independent-light-on-surface";
  s.width = 32;
  s.height = 32;
  s.camera.orthoHeight = 8;
  s.ambient = Vec(0.02, 0.02, 0.02);
  s.plane.albedo = Vec(0.6, 0.7, 0.8);
  s.lights = {
      point("p_on", Vec(0.125, 0, 0.125), 5, 5.0),
      point("p_low", Vec(-1.875, 0.003, 1.125), 4, 1e-4, Vec(1.0, 0.5, 0.25)),
      point("p_main", Vec(1.0, 1.5, -1.0), 10, 3.0),
  };
  return {s, {allLightNames(s), {}}};
}

SceneSpec elevenLightsScene() {
  SceneSpec s;
  s.name = "independent-eleven-lights";
  s.width = 48;
  s.height = 40;
  s.camera.perspective = true;
  s.camera.position = Vec(0.5, 9, 7);
  s.camera.target = Vec(0, 0, 0);
  s.camera.up = Vec(0, 1, 0);
  s.camera.fovYDeg = 55;
  s.lightsPerObject = true;
  s.ambient = Vec(0.01, 0.01, 0.01);
  s.plane.sizeX = 10;
  s.plane.sizeZ = 10;
  s.plane.subdivisions = 2;
  s.plane.albedo = Vec(0.9, 0.8, 0.7);
  const double intensities[11] = {2.0, 0.6, 3.2, 1.4, 0.3, 2.6, 1.0, 3.8, 0.45, 2.3, 1.7};
  for (int k = 0; k < 11; ++k) {
    const double angle = 2.0 * std::numbers::pi * k / 11.0;
    std::string name = "p";
    name += std::to_string(k);
    s.lights.push_back(point(name, Vec(3 * std::cos(angle), 1, 3 * std::sin(angle)), 8, intensities[k]));
  }
  return s;
}

PlaneCase perObjectTruncationCase() {
  return {elevenLightsScene(), {{"p7", "p2", "p5", "p9", "p0", "p10", "p3", "p6"}, {}}};
}

PlaneCase idealEveryLightCase() {
  const SceneSpec s = elevenLightsScene();
  return {s, {allLightNames(s), {}}};
}

PlaneCase legacyVertexLightsCase() {
  SceneSpec s;
  s.name = "independent-legacy";
  s.width = 64;
  s.height = 48;
  s.camera.orthoHeight = 11;  // 14.67 x 11 world units over a 10x10 plane
  s.camera.position = Vec(0.2, 10, 0.1);
  s.camera.target = Vec(0.2, 0, 0.1);
  s.profile = "legacy";
  s.ambient = Vec(0.03, 0.03, 0.04);
  s.plane.subdivisions = 4;
  s.plane.albedo = Vec(0.75, 0.6, 0.9);
  const auto onCircle = [](int k) {
    const double angle = 2.0 * std::numbers::pi * k / 7.0 + 0.3;
    return Vec(3 * std::cos(angle), 1.2, 3 * std::sin(angle));
  };
  s.lights = {
      directional("d0", Vec(0.5, -1, 0.3), 0.2),
      point("p1", onCircle(0), 7, 1.5),
      spot("s2", onCircle(1), Vec(0.1, -1, 0), 7, 90, 30, 4.0),
      point("p3", onCircle(2), 7, 0.8),
      spot("s4", onCircle(3), Vec(0, -1, 0.2), 7, 120, std::nullopt, 2.2),
      point("p5", onCircle(4), 7, 3.0),
      point("p6", onCircle(5), 7, 1.1),
      spot("s7", onCircle(6), Vec(0, -1, 0), 7, 150, 40, 0.6),
  };
  return {s, {{"d0", "s2", "p5", "s4"}, {"p1", "p6", "p3", "s7"}}};
}

// ---------------------------------------------------------------------------
// The reference renderer against the model

reference::ReferenceImages renderReference(const SceneSpec& s, bool ideal, bool keepExactValues) {
  const lighting::Scene scene = scene_input::loadSceneText(sceneJson(s), s.name + ".json");
  const auto prepared = lighting::prepareScene(scene);
  const lighting::Frame frame = lighting::prepareFrame(prepared, 0);
  reference::ReferenceOptions options;
  options.ideal = ideal;
  options.keepExactValues = keepExactValues;
  return reference::ReferenceRenderer(prepared).render(frame, options);
}

namespace {

constexpr double kRelativeTolerance = 1e-6;
// The relative test is floored at 1e-3 of the image's largest value: where a
// term falls to (near) zero at a cone, range or grazing edge, or a pixel is a
// thousand times darker than the brightest one, its value is a small remainder
// whose last digits depend on the rounding of the hit position (1e-16 of
// coordinates up to 1e5), which the two evaluations legitimately do differently.
constexpr double kFloorFraction = 1e-3;
constexpr double kMaxMaskedFraction = 0.05;
constexpr int kReportedFailures = 5;

}  // namespace

ComparisonResult compareWithExpected(const SceneSpec& s, const reference::ReferenceImages& images,
                                     const std::vector<Vec>& expected) {
  ComparisonResult result;
  const imaging::Image& value = images.value;
  const imaging::Image& tolerance = images.tolerance;
  EXPECT_EQ(value.width, s.width);
  EXPECT_EQ(value.height, s.height);
  EXPECT_EQ(value.channels, 4);
  EXPECT_EQ(tolerance.width, s.width);
  EXPECT_EQ(tolerance.height, s.height);
  EXPECT_GE(tolerance.channels, 3);
  if (value.width != s.width || value.height != s.height || value.channels != 4 || tolerance.width != s.width ||
      tolerance.height != s.height || tolerance.channels < 3)
    return result;

  double maxAbs = 0;
  for (const Vec& v : expected) maxAbs = std::max({maxAbs, std::abs(v.r), std::abs(v.g), std::abs(v.b)});
  const double floor = kFloorFraction * maxAbs;

  int failures = 0, nonFinite = 0, badTolerance = 0, badMask = 0, masked = 0;
  for (int j = 0; j < s.height; ++j)
    for (int i = 0; i < s.width; ++i) {
      const float mask = value.at(i, j, 3);
      if (mask != 0.0f && mask != 1.0f && ++badMask <= kReportedFailures)
        ADD_FAILURE() << "pixel (" << i << ", " << j << "): mask " << mask << " is neither 0 nor 1";
      for (int c = 0; c < 3; ++c) {
        const float v = value.at(i, j, c), t = tolerance.at(i, j, c);
        if (!std::isfinite(v) && ++nonFinite <= kReportedFailures)
          ADD_FAILURE() << "pixel (" << i << ", " << j << ") channel " << c << ": value " << v << " is not finite";
        if (!(std::isfinite(t) && t >= 0.0f) && ++badTolerance <= kReportedFailures)
          ADD_FAILURE() << "pixel (" << i << ", " << j << ") channel " << c << ": tolerance " << t
                        << " is not finite and >= 0";
      }
      if (mask == 0.0f) {
        ++masked;
        continue;
      }
      ++result.compared;
      const Vec& e = expected[std::size_t(j) * s.width + i];
      if (e != Vec(0.0)) ++result.lit;
      for (int c = 0; c < 3; ++c) {
        const double ref = value.at(i, j, c);
        const double diff = std::abs(ref - e[c]);
        const double scale = std::max(std::abs(e[c]), floor);
        const double relative = scale > 0 ? diff / scale : diff;
        if (std::isfinite(relative)) result.maxRelative = std::max(result.maxRelative, relative);
        if (!(diff <= kRelativeTolerance * scale) && ++failures <= kReportedFailures)
          ADD_FAILURE() << std::setprecision(17) << "pixel (" << i << ", " << j << ") channel " << c
                        << ": reference " << ref << ", expected " << e[c] << ", difference " << diff
                        << " (allowed " << kRelativeTolerance * scale << ", relative " << relative << ")";
      }
    }
  EXPECT_EQ(failures, 0) << "channels outside 1e-6 relative (first " << kReportedFailures << " shown)";
  EXPECT_EQ(nonFinite, 0);
  EXPECT_EQ(badTolerance, 0);
  EXPECT_EQ(badMask, 0);
  EXPECT_LT(masked, kMaxMaskedFraction * s.width * s.height)
      << masked << " of " << s.width * s.height << " pixels are masked on a plane scene";
  std::printf("[ %s ] largest relative difference %.3g over %d compared pixels (%d on the plane, %d masked)\n",
              s.name.c_str(), result.maxRelative, result.compared, result.lit, masked);
  return result;
}

ComparisonResult checkScene(const SceneSpec& s, const AppliedLights& applied, bool ideal) {
  SCOPED_TRACE("scene " + s.name + (ideal ? " (--ideal)" : ""));
  const reference::ReferenceImages images = renderReference(s, ideal);
  return compareWithExpected(s, images, expectedImage(s, applied));
}

// ---------------------------------------------------------------------------
// The reference's double values against the model, to 1e-9 relative

namespace {

constexpr double kExactRelativeTolerance = 1e-9;
// The floor, 1e-7 of the image's largest value, i.e. an absolute allowance of
// 1e-16 of it. Both evaluations find the hit point of a pixel centre in their
// own way (a ray against the plane here, the rasterised triangle there), so p
// differs by a few ulp of its coordinates (1e-16 relative). Terms that vanish at
// a cone, range or grazing edge are a difference of nearly equal numbers there
// (1 - square(distSqr * invRangeSq), dot(spotDir, L) * a + b, dot(N, L)), whose
// absolute error is a few ulp of the unattenuated term, itself no larger than the
// image's largest value; a pixel that such a remainder dominates cannot agree to
// 1e-9 of itself, only to about 1e-16 of the image's scale. With metallic 1 there
// is no ambient term (diffuse = 0) to keep a pixel away from 0 at those edges.
constexpr double kExactFloorFraction = 1e-7;

}  // namespace

ComparisonResult compareExact(const SceneSpec& s, const reference::ReferenceImages& images,
                              const std::vector<Vec>& expected) {
  ComparisonResult result;
  const imaging::Image& value = images.value;
  const std::size_t count = std::size_t(s.width) * s.height;
  EXPECT_EQ(value.width, s.width);
  EXPECT_EQ(value.height, s.height);
  EXPECT_EQ(value.channels, 4);
  EXPECT_EQ(images.exactValue.size(), count) << "render with keepExactValues";
  EXPECT_EQ(expected.size(), count);
  if (value.width != s.width || value.height != s.height || value.channels != 4 || images.exactValue.size() != count ||
      expected.size() != count)
    return result;

  double maxAbs = 0;
  for (const Vec& v : expected) maxAbs = std::max({maxAbs, std::abs(v.r), std::abs(v.g), std::abs(v.b)});
  const double floor = kExactFloorFraction * maxAbs;

  int failures = 0, nonFinite = 0, badMask = 0, masked = 0;
  double unfloored = 0;  // the largest |difference| / |expected| where expected != 0, for the log
  int worstI = -1, worstJ = -1;
  for (int j = 0; j < s.height; ++j)
    for (int i = 0; i < s.width; ++i) {
      const std::size_t k = std::size_t(j) * s.width + i;
      const Vec& ref = images.exactValue[k];
      for (int c = 0; c < 3; ++c)
        if (!std::isfinite(ref[c]) && ++nonFinite <= kReportedFailures)
          ADD_FAILURE() << "pixel (" << i << ", " << j << ") channel " << c << ": exact value " << ref[c]
                        << " is not finite";
      const float mask = value.at(i, j, 3);
      if (mask != 0.0f && mask != 1.0f && ++badMask <= kReportedFailures)
        ADD_FAILURE() << "pixel (" << i << ", " << j << "): mask " << mask << " is neither 0 nor 1";
      if (mask == 0.0f) {
        ++masked;
        continue;
      }
      ++result.compared;
      const Vec& e = expected[k];
      if (e != Vec(0.0)) ++result.lit;
      for (int c = 0; c < 3; ++c) {
        const double diff = std::abs(ref[c] - e[c]);
        const double scale = std::max(std::abs(e[c]), floor);
        const double relative = scale > 0 ? diff / scale : diff;
        if (std::isfinite(relative)) result.maxRelative = std::max(result.maxRelative, relative);
        if (e[c] != 0.0 && std::isfinite(diff / std::abs(e[c])) && diff / std::abs(e[c]) > unfloored) {
          unfloored = diff / std::abs(e[c]);
          worstI = i;
          worstJ = j;
        }
        if (!(diff <= kExactRelativeTolerance * scale) && ++failures <= kReportedFailures)
          ADD_FAILURE() << std::setprecision(17) << "pixel (" << i << ", " << j << ") channel " << c
                        << ": reference (double) " << ref[c] << ", expected " << e[c] << ", difference " << diff
                        << " (allowed " << kExactRelativeTolerance * scale << ", relative " << relative << ")";
      }
    }
  EXPECT_EQ(failures, 0) << "channels outside 1e-9 relative (first " << kReportedFailures << " shown)";
  EXPECT_EQ(nonFinite, 0);
  EXPECT_EQ(badMask, 0);
  EXPECT_LT(masked, kMaxMaskedFraction * s.width * s.height)
      << masked << " of " << s.width * s.height << " pixels are masked on a plane scene";
  std::printf(
      "[ %s ] largest relative difference (double) %.3g (without the floor %.3g, pixel (%d, %d)) over %d compared "
      "pixels (%d on the plane, %d masked)\n",
      s.name.c_str(), result.maxRelative, unfloored, worstI, worstJ, result.compared, result.lit, masked);
  return result;
}

ComparisonResult checkSceneExact(const SceneSpec& s, const AppliedLights& applied) {
  SCOPED_TRACE("scene " + s.name + " (exact)");
  const reference::ReferenceImages images = renderReference(s, false, /*keepExactValues=*/true);
  return compareExact(s, images, expectedImage(s, applied));
}

}  // namespace independent_plane
