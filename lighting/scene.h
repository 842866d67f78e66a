// The validated scene of SPEC section 2. Every field holds its default when the
// file leaves it out; scene_loader.cpp is the only place that fills these in.
#pragma once

#include <glm/vec3.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace lighting {

using Vec3 = glm::dvec3;

struct ImageSize {
  int width = 128;
  int height = 128;
};

enum class Projection { Perspective, Orthographic };

struct Camera {
  Vec3 position{0, 10, 0};
  Vec3 target{0, 0, 0};
  Vec3 up{0, 0, -1};
  Projection projection = Projection::Orthographic;
  double fovYDeg = 60;      // perspective only; not in SPEC's example, see docs/scene-format.md
  double orthoHeight = 10;  // orthographic only: world units of the vertical extent
  double nearPlane = 0.1;
  double farPlane = 100;
};

struct Mesh;  // mesh.h

// Plane, sphere and box are generated from their parameters (SPEC 2);
// Imported holds triangles read from a glTF file (SPEC 2.1), already in world
// space (the object's transform stays the identity).
enum class MeshType { Plane, Sphere, Box, Imported };

struct MeshSpec {
  MeshType type = MeshType::Plane;
  double planeSizeX = 10, planeSizeZ = 10;
  int subdivisions = 1;
  double sphereRadius = 0.5;
  int sphereSegments = 32, sphereRings = 16;
  Vec3 boxSize{1, 1, 1};
  std::shared_ptr<const Mesh> imported;  // Imported only: world-space triangles
};

struct Transform {
  Vec3 translate{0, 0, 0};
  Vec3 rotateDeg{0, 0, 0};  // R = Ry(y) * Rx(x) * Rz(z)
  double scale = 1;         // uniform only (SPEC 1)
};

// SPEC 2 `material.brdf`: Lambert (SPEC 3.1-3.2 as written) or the custom
// pipeline's BRDF (SPEC 3.8), which reads metallic and smoothness.
enum class Brdf { Lambert, Srp };

struct Object {
  std::string name;
  MeshSpec mesh;
  Transform transform;
  Vec3 albedo{1, 1, 1};
  Brdf brdf = Brdf::Lambert;
  double metallic = 0;      // srp only, [0, 1]
  double smoothness = 0.5;  // srp only, [0, 1]
  bool isStatic = false;
  int lightmapResolution = 0;

  bool hasLightmap() const { return isStatic && lightmapResolution > 0; }
};

enum class LightType { Directional, Point, Spot };

// SPEC 2 and 3.10: a real-time light's cookie, its images read by the loader
// (one channel each: the alpha channel when the file has one, else the
// first; row 0 is v = 0). Directional: one image tiled every `size` metres;
// spot: one image projected over the cone; point: a cube of six faces in the
// order +X, -X, +Y, -Y, +Z, -Z, square and equal in size.
struct CookieImage {
  int width = 0, height = 0;
  std::vector<float> texels;  // row-major, row 0 first
  float at(int i, int j) const { return texels[std::size_t(j) * width + i]; }
};
struct Cookie {
  std::vector<std::string> files;  // as resolved against the scene file's folder
  std::vector<std::shared_ptr<const CookieImage>> images;  // 1, or 6 for a cube
  double sizeX = 1, sizeY = 1;     // directional: the world size of one tile
};
// SPEC 2 and 3.9: a real-time light's shadow map. Present on a `realtime`
// light with `shadows` (the defaults below when the file leaves
// `shadow_map` out); absent otherwise.
enum class ShadowFilter { Hard, Bilinear, Tent3x3 };
struct ShadowMapSpec {
  int resolution = 512;  // a power of two in [16, 4096]
  ShadowFilter filter = ShadowFilter::Bilinear;
  double depthBias = 0.05;   // world units, along L
  double normalBias = 0;     // world units, along N
  double nearPlane = 0.05;   // spot and point: in (0, range)
  Vec3 center{0, 0, 0};      // directional only
  double extent = 10;        // directional only: the box's half-size
};
enum class LightMode { Realtime, Mixed, Baked };
enum class BakeFalloff { InverseSquared, InverseSquaredNoRange, Legacy };

struct Light {
  std::string name;
  LightType type = LightType::Spot;
  Vec3 position{0, 2, 0};
  Vec3 direction{0, -1, 0};  // the way the light travels, normalised by the loader
  double range = 6;
  double spotAngleDeg = 60;                   // the full outer cone
  std::optional<double> innerSpotAngleDeg;    // absent: the legacy rule (SPEC 3.4)
  Vec3 color{1, 1, 1};
  double intensity = 2;
  LightMode mode = LightMode::Realtime;
  bool shadows = false;
  double shadowStrength = 1;
  BakeFalloff bakeFalloff = BakeFalloff::InverseSquared;
  std::optional<Cookie> cookie;  // realtime lights only (SPEC 3.10)
  std::optional<ShadowMapSpec> shadowMap;  // realtime lights with shadows only (SPEC 3.9)

  Vec3 finalColor() const { return color * intensity; }
};

enum class Profile { Srp, Legacy };
enum class RenderPath { Forward, Deferred };
enum class DeferredBuffer { Hdr32, Hdr16, Ldr8 };

struct Pipeline {
  Profile profile = Profile::Srp;
  RenderPath path = RenderPath::Forward;
  bool lightsPerObject = false;
  DeferredBuffer deferredBuffer = DeferredBuffer::Hdr32;
  // Extension (docs/model.md, popping mitigation): the last this-many kept
  // point/spot lights fade out toward the cut; 0 is the plain cut of SPEC 5.1.
  int fadeLastLights = 0;
  // SPEC 3.9: real-time shadows fade out over the last 20% of this view
  // depth; 0 is no fading.
  double shadowDistance = 0;
};

struct CameraKeyframe {
  Vec3 position;
  Vec3 target;
};

struct Frames {
  int count = 1;
  std::vector<CameraKeyframe> cameraPath;  // empty, or at least two keyframes
};

// What a scene is compared against (extension of SPEC 2, docs/scene-format.md):
// the reference of the model, or an idealised one in which the baked lights on
// lightmapped objects are evaluated in real time per pixel (docs/model.md).
enum class CompareAgainst { Reference, Realtime };

struct Expectation {
  double toleranceScale = 1;
  long long maxFailingPixels = 0;
  bool expectFail = false;
  CompareAgainst against = CompareAgainst::Reference;
};

struct Scene {
  std::string sourcePath;  // the file it was loaded from, for messages
  std::string name;
  std::string description;
  ImageSize image;
  Camera camera;
  Pipeline pipeline;
  Vec3 ambient{0, 0, 0};
  std::vector<Object> objects;
  std::vector<Light> lights;
  Frames frames;
  Expectation expect;
  // What the loader accepted but ignored, each naming the file and where
  // (glTF content outside the model, SPEC 2.1); the command line prints them.
  std::vector<std::string> warnings;
};

}  // namespace lighting
