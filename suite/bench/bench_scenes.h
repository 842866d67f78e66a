// The synthetic scenes of the frame benchmarks (docs/bench-format.md): a
// field of floor tiles seen from straight above with point lights over it,
// sized so every pixel is covered and every light is in view. The 1280x720
// 64-light field (`lights64-1280x720`) and the cost curves (`curve-lights`,
// `curve-resolution`, `curve-objects`) are all this one generator. The
// lightmap scene (`lightmap-1280x720`, SPEC 9's baked lightmaps at several
// resolutions) is a second one: one lightmapped plane under a few point lights.
#pragma once

#include "lighting/light_clusters.h"
#include "lighting/scene.h"

#include <optional>
#include <string>
#include <string_view>

namespace bench {

// The `mode` part of a benchmark name: which pipeline and shader variant.
enum class FrameMode {
  AllLights,   // srp forward, every kept light per pixel
  PerObject,   // srp forward, per-object lists (at most 8 lights per object)
  Legacy4x4,   // legacy profile: lists always on, 4 pixel + 4 vertex lights, 16 kept lights
  // srp deferred (SPEC 3.7): every kept light as one volume draw into the
  // light buffer of that format (lists do not apply to deferred)
  DeferredHdr32,
  DeferredHdr16,
  DeferredLdr8,
  // srp forward, each pixel over its cluster's lights (Forward+:
  // lighting/light_clusters.h): the all-lights scene, binned per frame. A
  // benchmark mode, never a suite scene's.
  Clustered,
};

// all-lights, per-object, legacy-4+4, deferred-<buffer> (the buffer's
// scene-format name, lighting::deferredBufferName), clustered
// (lighting::kClusteredModeName).
std::string modeName(FrameMode mode);
// The light buffer of a deferred mode; nullopt for the forward modes.
std::optional<lighting::DeferredBuffer> deferredBufferOf(FrameMode mode);
// The mode a scene's pipeline is drawn in (a suite scene's benchmark name):
// the inverse of what fieldScene sets for a mode.
FrameMode frameModeOf(const lighting::Pipeline& pipeline);

// The field's depth in world units: the orthographic view's height.
inline constexpr double kFieldZ = 7.2;

struct FieldSpec {
  int width = 1280, height = 720;
  // The floor: tileColumns x tileRows tiles covering exactly the view
  // (7.2 world units tall, 7.2 * width / height wide).
  int tileColumns = 8, tileRows = 8;
  // A 0.5 box on every other interior tile corner (16 on the 8x8 field).
  bool boxes = true;
  // Point lights 0.4 above the centres of a lightColumns x lightRows grid
  // over the field; the range scales with the cell (0.85 on 1.6 x 0.9 cells).
  int lightColumns = 8, lightRows = 8;
  FrameMode mode = FrameMode::AllLights;
  // Each light's range times this: 1 is the 64-light field; kDenseFieldRangeScale
  // the dense field, where per-object lists truncate.
  double rangeScale = 1.0;
  // Every tile and box with the srp BRDF (SPEC 3.8; kFieldMetallic,
  // kFieldSmoothness) instead of Lambert: what the specular lobe costs.
  bool specularBrdf = false;
  // The cookie modes (SPEC 3.10 and 9, "cookies on and off"). cookieLights:
  // the grid with the lights that carry the cookies: one directional light
  // over the field (kFieldCookieDirection) is added and the point lights of
  // kFieldCookieSpots become spots pointing straight down (kFieldSpotAngleDeg);
  // still 64 point/spot lights, all in view, and one directional. cookies:
  // the same lights (cookieLights implied) with procedural cookies of
  // cookieSize texels a side (per face for a cube): a tiled 2D cookie on the
  // directional light, a projected 2D one on each spot, and a cube cookie on
  // each point light of kFieldCookieCubes. That is 3 2D and 2 cube cookies,
  // within a frame's slots (lighting::kMaxCookieTextures, kMaxCookieCubes).
  bool cookieLights = false;
  bool cookies = false;
  int cookieSize = 256;
  // The shadow modes (SPEC 3.9 and 9, shadow maps at 256 to 4096 texels with
  // each filter, against ray-traced shadows): shadowLights: the cookie
  // field's lights (the directional light and the two spots, cookieLights),
  // with the point light of kFieldShadowCube; shadows: the same four lights
  // casting real-time shadows (the 0.5 boxes onto the tiles) from maps of
  // shadowResolution texels a side with shadowFilter (a point light's cube
  // takes bilinear where the others take tent3x3, which SPEC 2 does not
  // allow on it). That is 3 2D maps and 1 cube, within a frame's slots.
  bool shadowLights = false;
  bool shadows = false;
  int shadowResolution = 1024;
  lighting::ShadowFilter shadowFilter = lighting::ShadowFilter::Bilinear;
};

// The cookie field's lights (FieldSpec::cookieLights): the grid cells
// (column, row) of the two spots and of the two cube-cookied point lights,
// the directional light's direction (the way its light travels) and its
// tiled cookie's world size, and the spots' outer and inner cone.
struct FieldCell {
  int column, row;
};
inline constexpr FieldCell kFieldCookieSpots[] = {{2, 5}, {5, 2}};
inline constexpr FieldCell kFieldCookieCubes[] = {{1, 1}, {6, 6}};
inline constexpr double kFieldCookieDirection[] = {0.35, -1.0, 0.2};
inline constexpr double kFieldCookieTile = 1.8;  // world units a repeat, both axes
inline constexpr double kFieldSpotAngleDeg = 120, kFieldSpotInnerAngleDeg = 90;
// The shadow field's point light with a cube map (FieldSpec::shadows), and
// its maps' shape: the directional box covers the whole field.
inline constexpr FieldCell kFieldShadowCube = {1, 1};
inline constexpr double kFieldShadowExtent = 6.6;  // half of the 12.8-unit field, and a margin
inline constexpr double kFieldShadowDepthBias = 0.05, kFieldShadowNormalBias = 0.03, kFieldShadowNear = 0.05;

// The shadow modes' map resolutions (SPEC 9: 256 to 4096 with each
// filter): `hard` at every one, the resolution axis; `bilinear` and
// `tent3x3` at both ends and the middle, which spans the same axis in 9
// points instead of 15 (the full bench's 10-minute budget: a
// shadowed 1280x720 frame takes some 0.7 s on lavapipe and llvmpipe, so each
// mode costs 6 draws and a compare_Yee, about 6 s).
inline constexpr int kShadowResolutions[] = {256, 512, 1024, 2048, 4096};
inline constexpr int kFilteredShadowResolutions[] = {256, 1024, 4096};

// The dense field: every range 5.5 times the 64-light field's
// (0.85 -> 4.675 on 1.6 x 0.9 cells), so every tile and box is touched by 23
// lights or more (a corner tile the fewest; docs/bench-format.md derives it):
// per-object lists (at most 8 per object, SPEC 5.2) drop most of a pixel's
// light, the clustered mode drops none.
inline constexpr double kDenseFieldRangeScale = 5.5;
inline constexpr int kDenseFieldLeastObjectLights = 20;  // the fewest an object's list must hold

// The srp material of the field's specular modes: a highlight of a few
// pixels under each light seen from straight above (smoothness 0.8), with a
// coloured F0 (metallic 0.3 of the tiles' and boxes' albedo).
inline constexpr double kFieldMetallic = 0.3;
inline constexpr double kFieldSmoothness = 0.8;

// The scene of `spec` (the mode's profile and lists set; the shader variant
// is the backend's business).
lighting::Scene fieldScene(const FieldSpec& spec, const std::string& name);

// `lightmap-1280x720`: one static plane filling the view (12.8 x 7.2, seen
// from straight above) with lightmap_resolution `resolution`, under five
// point lights of inverse-squared bake falloff, 0.4 to 1.2 above it (low
// lights make sharp pools, the detail a coarse map loses), and a black box
// (albedo 0, so it looks the same baked or not). With `shadows` the highest
// light has `shadows` and the box casts its shadow on the plane. `baked`: the lights are `baked` (the plane's
// lightmap holds them; nothing is lit in real time); else `realtime`, the
// same lights lit per pixel, and the plane has no lightmap: the error
// baseline of the lightmap modes.
struct LightmapSpec {
  int width = 1280, height = 720;
  int resolution = 64;
  bool baked = true;
  bool shadows = false;  // the shadowed light (false: every light unshadowed)
};

lighting::Scene lightmapScene(const LightmapSpec& spec, const std::string& name);

// The resolutions of the `lightmap-N` modes: 16, 32, ... 512.
inline constexpr int kLightmapResolutions[] = {16, 32, 64, 128, 256, 512};

// A light grid of `count` lights (1, 2, 4, ... powers of two): columns >= rows.
void lightGridFor(int count, int& columns, int& rows);

}  // namespace bench
