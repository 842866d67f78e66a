// The names bench.json's benchmarks and counters go by (docs/bench-format.md),
// once: the bench programs (suite/bench) write them and the bench pages
// (reports/bench_*) read them from here, so neither can rename one alone.
#pragma once

#include <string_view>

namespace results::bench {

// A benchmark's kind, the first part of its name <kind>/<scene>/<mode>[/<x>].
inline constexpr std::string_view kFrame = "frame";
inline constexpr std::string_view kFrameReadback = "frame_readback";
inline constexpr std::string_view kUpload = "upload";
inline constexpr std::string_view kPipeline = "pipeline";
inline constexpr std::string_view kPrepare = "prepare";

// Counters: the frame's load, its throughput and the cost model's limit.
inline constexpr std::string_view kPixels = "pixels";
inline constexpr std::string_view kTriangles = "triangles";
inline constexpr std::string_view kLights = "lights";
inline constexpr std::string_view kLightsPerPixel = "lights_per_pixel";
inline constexpr std::string_view kPixelsPerS = "pixels_per_s";
inline constexpr std::string_view kPixelLightEvalsPerS = "pixel_light_evals_per_s";
inline constexpr std::string_view kFlopsPerPixelLight = "flops_per_pixel_light";
inline constexpr std::string_view kLimitMs = "limit_ms";
// The image's error against the reference.
inline constexpr std::string_view kErrRmse = "err_rmse";
inline constexpr std::string_view kErrMaxAbs = "err_max_abs";
inline constexpr std::string_view kErrPsnrDb = "err_psnr_db";
inline constexpr std::string_view kErrPerceptualFail = "err_perceptual_fail";
inline constexpr std::string_view kErrNonfinitePixels = "err_nonfinite_pixels";
// Baked lighting.
inline constexpr std::string_view kBakeMs = "bake_ms";
inline constexpr std::string_view kBakeRuns = "bake_runs";
inline constexpr std::string_view kLightmapTexels = "lightmap_texels";
// The frame's times beside the benchmark's own.
inline constexpr std::string_view kWallMs = "wall_ms";
inline constexpr std::string_view kDeviceMs = "device_ms";
inline constexpr std::string_view kShadowPassMs = "shadow_pass_ms";
inline constexpr std::string_view kDeviceTimeFlagged = "device_time_flagged";

}  // namespace results::bench
