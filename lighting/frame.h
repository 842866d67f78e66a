// A frame ready to render: the camera of that frame, the scene's geometry, and
// every decision of SPEC 5 (visible set, packed lights, per-object lists,
// shadow-mask channels). Backends and the reference both start from a Frame;
// neither decides on its own which lights count.
#pragma once

#include "lighting/baked_lighting.h"
#include "lighting/camera_view.h"
#include "lighting/cookie_slots.h"
#include "lighting/mesh.h"
#include "lighting/object_light_lists.h"
#include "lighting/scene.h"
#include "lighting/shadow_mask_channels.h"
#include "lighting/shadow_slots.h"
#include "lighting/transform.h"
#include "lighting/visible_lights.h"

#include <memory>
#include <vector>

namespace lighting {

struct LightClusters;  // light_clusters.h

struct ObjectGeometry {
  Mesh mesh;                  // local space
  ObjectTransform transform;  // local to world
  BoundingSphere bounds;      // world space (SPEC 5.2)
};

// What does not change from frame to frame: meshes, transforms, bounds, the
// bake-time shadow-mask assignment and the baked maps.
struct PreparedScene {
  Scene scene;
  std::vector<ObjectGeometry> objects;
  ShadowMaskAssignment shadowMask;
  // The lightmaps and shadow masks (SPEC 3.6); null until baked. A scene with
  // a lightmapped object must come from baking::prepareBakedScene: the
  // reference and the backends refuse to draw one without its maps.
  std::shared_ptr<const BakedLighting> baked;

  bool needsBake() const;  // some object has a lightmap
  // The maps of `object`; throws std::logic_error when the scene needs a bake
  // that never happened. Null for an object without maps.
  const ObjectBake* bakeOf(int object) const;
};

// Geometry and shadow-mask channels only; no bake (baking/bake.h adds it).
std::shared_ptr<const PreparedScene> prepareScene(Scene scene);

// Which parts of the model a frame uses, so a backend can switch the rest off.
struct ShaderFeatures {
  bool directionalLights = false;
  bool pointLights = false;
  bool spotLights = false;
  bool perObjectLists = false;
  bool vertexLights = false;   // legacy profile only
  bool shadowMask = false;     // a mixed light with a channel on an object with a mask
  bool lightmap = false;       // some object has a lightmap (SPEC 3.6)
  bool ldr8Buffer = false;     // deferred path with the ldr8 light buffer (SPEC 3.7)
  bool ambient = false;
  bool specularBrdf = false;   // some object has the srp BRDF (SPEC 3.8)
  bool cookies = false;        // some kept light has a cookie (SPEC 3.10)
  bool shadowMaps = false;     // some kept light has a real-time shadow map (SPEC 3.9)
  // The slots in use, counted from the first of each kind (cookie_slots.h,
  // shadow_slots.h fill them in order): the shaders look up only these.
  int cookieTextures = 0;      // 2D cookie slots, 0 to kMaxCookieTextures
  int cookieCubes = 0;         // cube cookie slots, 0 to kMaxCookieCubes
  int shadowMapTextures = 0;   // 2D shadow-map slots, 0 to kMaxShadowMaps
  int shadowMapCubes = 0;      // cube shadow-map slots, 0 to kMaxShadowCubes
  bool shadowTent = false;     // some 2D shadow-map slot filters tent3x3 (SPEC 3.9)
  // Forward+ (a benchmark mode, never the model's): each fragment
  // loops over its cluster's lights (Frame::clusters) instead of every kept one.
  bool clusteredLights = false;
};

// The lights that shade one object, as scene light indices.
struct ObjectLights {
  std::vector<int> perPixel;
  std::vector<int> perVertex;  // legacy list positions 4-7
};

struct Frame {
  std::shared_ptr<const PreparedScene> prepared;
  int index = 0;
  CameraView view;
  LightSelection selection;
  std::vector<ObjectLightList> objectLists;  // empty when per-object lists are not in use
  ShaderFeatures features;
  CookieSlots cookies;  // SPEC 3.10: the kept lights' cookies and their texture slots
  ShadowSlots shadows;  // SPEC 3.9: the kept lights' shadow maps and their depth-texture slots
  // The clustered mode's light lists (useLightClusters, light_clusters.h);
  // null in every mode of the model.
  std::shared_ptr<const LightClusters> clusters;

  const Scene& scene() const { return prepared->scene; }
  // False on the deferred path: it lights every kept light per pixel.
  static bool perObjectListsEnabled(const Scene& scene);
  // The lights that reach an object under the scene's budgets (SPEC 4). The
  // deferred path (SPEC 3.7): every kept light per pixel, no vertex lights.
  ObjectLights lightsForObject(int object) const;
  // SPEC 6 `--ideal`: every light that is not baked, per pixel, no budgets. A
  // mixed light demoted by SPEC 5.3 counts as baked: it lives in the lightmap,
  // which `--ideal` keeps.
  ObjectLights idealLightsForObject() const;
};

// Frame `index` (0-based; must be < scene.frames.count).
Frame prepareFrame(std::shared_ptr<const PreparedScene> prepared, int index);

}  // namespace lighting
