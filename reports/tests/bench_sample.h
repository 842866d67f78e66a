// A small hand-written bench.json (docs/bench-format.md) for the benchmark
// pages: two backends that ran (vulkan with device times and Google
// Benchmark's aggregates, gl-egl with repetitions only and times in us), one
// that is NotSupported, the synthetic scene in four and three modes with
// error counters, cost curves, CPU preparation curves with complexity fits,
// a failed benchmark, and text that needs escaping.
//
// The frame benchmarks of lights64-1280x720 (median ms, err_rmse):
//   vulkan  all-lights 10 1e-4   per-object 6 5e-3   legacy-4+4 3 2e-2   full-shader 12 1e-4
//   gl-egl  all-lights 20 5e-5   per-object 8 8e-3   legacy-4+4 2.5 3e-2
// Pareto front (no other point both at least as fast and at least as
// accurate, better in one): gl-egl/legacy-4+4, vulkan/legacy-4+4,
// vulkan/per-object, vulkan/all-lights, gl-egl/all-lights. Not on it:
// vulkan/full-shader (slower than vulkan/all-lights, same error) and
// gl-egl/per-object (slower and less accurate than vulkan/per-object).
// Among vulkan's own points the front is legacy-4+4, per-object, all-lights.
//
// Plots: index.html 7 (1 scatter, curve-lights x {all-lights, per-object},
// curve-resolution, curve-objects, 2 prepare curves); vulkan.html 4 (scatter,
// 3 curves); gl-egl.html 2 (scatter, curve-lights); gl-osmesa.html 0.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <utility>
#include <vector>

namespace reports::testing {

nlohmann::ordered_json sampleBench();

// The speed-against-error plot's worst cases, on one Vulkan backend:
// lights64-1280x720 with 30 modes at one error (0.01), their times spread
// over 1 to 100 ms, and 8 more modes at one spot (5 ms, 1e-5); and a second
// scene of 14 modes crowded near 0.01 and 3 near 1e-5 (a full bench's
// shadow and all-lights clusters). No label may overlap another or a point.
nlohmann::ordered_json crowdedBench();

// A plain Google Benchmark file: `repetitions` of `name` with these real
// times in ms (run_type "iteration", no aggregates).
nlohmann::ordered_json plainBenchmarkFile(const std::vector<std::pair<std::string, std::vector<double>>>& runs);

}  // namespace reports::testing
