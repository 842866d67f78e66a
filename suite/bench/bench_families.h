// The families of frame benchmarks (docs/bench-format.md), each in its
// own file, each registering through the Registrar:
//   field_modes.cpp      the 1280x720 64-light field in every mode (frame,
//                        frame_readback, pipeline), with error counters
//   cookie_uploads.cpp   upload: the cookie field's cookies to the device
//   lightmap_modes.cpp   lightmap-N against the same lights in real time
//   cost_curves.cpp      curve-lights, curve-resolution, curve-objects
//   suite_scenes.cpp     --suite_scenes: frame 0 of every suite scene
#pragma once

#include "suite/bench/bench_frame.h"
#include "suite/bench/bench_registrar.h"
#include "suite/bench/bench_scenes.h"
#include "suite/bench/run_state.h"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace bench {

// The 64-light field's size (the bench's budgets): 1280x720, the
// size every number of docs/performance.md is of; 160x90 on a slow driver
// (driver_speed.h: a sixty-fourth of the pixels); 320x180 with --quick,
// which proves each mode runs and measures nothing (160x90 on a slow driver). Its scene name,
// `lights64-<W>x<H>`, says which, in every benchmark name.
struct FieldSize {
  int width, height;
};
FieldSize fieldSize(const RunState& run);
std::string fieldSceneName(const RunState& run);

// The cookie modes of the field (SPEC 3.10 and 9, cookies on and off):
// `cookies` is the field with FieldSpec::cookies, `cookie-lights` the same
// lights without their cookies (FieldSpec::cookieLights).
inline constexpr const char* kCookiesMode = "cookies";
inline constexpr const char* kCookieLightsMode = "cookie-lights";
// The shadow modes of the field (SPEC 3.9 and 9): `shadows-<filter>-<N>`, the
// field with FieldSpec::shadows at N texels with that filter, and
// `shadow-lights`, the same lights casting nothing (FieldSpec::shadowLights).
inline constexpr const char* kShadowLightsMode = "shadow-lights";
std::string shadowModeName(lighting::ShadowFilter filter, int resolution);

// One mode of the field: its benchmark name, its scene and its shader variant.
struct FieldModeSpec {
  std::string name;
  FieldSpec field;
  bool fullShader = false;
};
// The field's modes in the order they are registered, in the set of a run
// with --quick (`quick`), on a slow driver (`slow`) or on a second context
// path to a driver (`lightPathsOnly`: all-lights, per-object, legacy-4+4 and
// the deferred modes).
std::vector<FieldModeSpec> fieldModeSpecs(bool quick, bool slow, bool lightPathsOnly = false);

// The field's frames by mode name, each made (its scene built and its load
// traced) when a benchmark the filter keeps first needs it.
using NamedFrames = std::vector<std::pair<std::string, LazyFrame>>;
struct FieldModes {
  NamedFrames shipped, full, pipeline;  // specialised shaders, full shader, pipeline benchmarks
};
FieldModes fieldModes(const RunState& run);
// frame of each and (but on a slow driver) frame_readback of the light-path modes.
void registerFieldModes(Registrar& r, const NamedFrames& frames);
void registerFieldPipelines(Registrar& r, const NamedFrames& frames);

// The dense field (dense64-<W>x<H>, FieldSpec::rangeScale =
// kDenseFieldRangeScale) in all-lights, per-object and clustered: frame only,
// each with its error against the dense field's ideal.
std::string denseFieldSceneName(const RunState& run);
NamedFrames denseFieldModes(const RunState& run);
void registerDenseFieldModes(Registrar& r, const NamedFrames& frames);

// The mesh field (meshes64-<W>x<H>, mesh_field.cpp): the field with eight
// imported 2CylinderEngine.glb meshes instead of its boxes and half its lights
// spots, in every light path; empty (with a note) without the package.
NamedFrames meshFieldModes(const RunState& run);
void registerMeshFieldModes(Registrar& r, const NamedFrames& frames);

// upload/<b>/lights64-1280x720/cookies/<N>: prepareTextures of a fresh
// prepared scene of the cookie field with N x N cookies, on the shipped-shader
// backend (registered with its benchmarks, before the full-shader ones).
void registerCookieUploads(Registrar& r);
// The cookie sides of the upload benchmark: 64, 256, 1024 (256 with --quick).
std::vector<int> cookieUploadSizes(bool quick);

void registerLightmapModes(Registrar& r);
void registerCurves(Registrar& r);
void registerSuiteScenes(Registrar& r);

}  // namespace bench
