// The four families of frame benchmarks (docs/bench-format.md), each in its
// own file, each registering through the Registrar:
//   field_modes.cpp      the 1280x720 64-light field in every mode (frame,
//                        frame_readback, pipeline), with error counters
//   lightmap_modes.cpp   lightmap-N against the same lights in real time
//   cost_curves.cpp      curve-lights, curve-resolution, curve-objects
//   suite_scenes.cpp     --suite_scenes: frame 0 of every suite scene
#pragma once

#include "suite/bench/bench_frame.h"
#include "suite/bench/bench_registrar.h"
#include "suite/bench/run_state.h"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace bench {

// The field's frames by mode name, made (and their loads traced) up front.
using NamedFrames = std::vector<std::pair<std::string, std::shared_ptr<const BenchFrame>>>;
struct FieldModes {
  NamedFrames shipped, full, pipeline;  // specialised shaders, full shader, pipeline benchmarks
};
FieldModes fieldModes(const RunState& run);
// frame and (but on a slow driver) frame_readback of each.
void registerFieldModes(Registrar& r, const NamedFrames& frames);
void registerFieldPipelines(Registrar& r, const NamedFrames& frames);

void registerLightmapModes(Registrar& r);
void registerCurves(Registrar& r);
void registerSuiteScenes(Registrar& r);

// The field's scene name in every benchmark name.
inline constexpr const char* kFieldScene = "lights64-1280x720";

}  // namespace bench
