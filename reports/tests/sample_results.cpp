#include "reports/tests/sample_results.h"

namespace reports::testing {

// JUnit, per suite:            tests failures errors skipped
//   vulkan                       4      1       1      0     Pass Fail QualityWarning Crash
//   gl-egl-softpipe              6      2       1      2     Pass ExpectedFail Timeout UnexpectedPass NotSupported Fail
//   gl-osmesa                    1      0       0      1     the backend is NotSupported, no tests
//   mutants                      4      1       1      0     killed killed survived Crash
//   all                         15      4       3      3
// The HTML shows images of the two Fail tests and a thumbnail of each killed
// mutant: 8 <img>.
nlohmann::ordered_json sampleResults() {
  return nlohmann::ordered_json::parse(R"json(
{
  "format": "lightcts-results", "version": 1,
  "lightcts_revision": "v0.1-42-gabc1234",
  "started_utc": "2026-11-25T10:00:00Z",
  "duration_s": 93.25,
  "command": "lightcts run --out out/run",
  "machine": {"hostname": "ci-1", "cpu": "Test CPU <8 cores>", "cores": 2, "os": "Debian GNU/Linux 12 (bookworm)"},
  "scenes_dir": "suite/scenes",
  "timeout_s": 120,
  "backends": [
    {"backend": "vulkan", "api_backend": "vulkan", "driver_option": "", "status": "ran", "message": "",
     "device": {"name": "llvmpipe (LLVM 15.0.6, 256 bits)", "driver": "llvmpipe", "driver_version": "Mesa 22.3.6",
                "api_version": "1.3.230", "selected_by": "default"},
     "expected_failures_file": "",
     "counts": {"Pass": 1, "Fail": 1, "QualityWarning": 1, "NotSupported": 0, "Crash": 1, "Timeout": 0,
                "ExpectedFail": 0, "UnexpectedPass": 0},
     "wall_s": 20.5},
    {"backend": "gl-egl-softpipe", "api_backend": "gl-egl", "driver_option": "softpipe", "status": "ran", "message": "",
     "device": {"name": "softpipe", "driver": "softpipe", "driver_version": "Mesa 22.3.6", "api_version": "4.5",
                "selected_by": "--driver softpipe"},
     "expected_failures_file": "suite/expected-failures/softpipe.txt",
     "counts": {"Pass": 1, "Fail": 1, "QualityWarning": 0, "NotSupported": 1, "Crash": 0, "Timeout": 1,
                "ExpectedFail": 1, "UnexpectedPass": 1},
     "wall_s": 60.0},
    {"backend": "gl-osmesa", "api_backend": "gl-osmesa", "driver_option": "", "status": "NotSupported",
     "message": "libOSMesa.so.8 not found", "log": "logs/gl-osmesa.log", "device": null, "expected_failures_file": "", "counts": null,
     "wall_s": 0.01}
  ],
  "tests": [
    {"name": "attenuation.point-d-0.vulkan", "group": "attenuation", "scene": "point-d-0",
     "scene_file": "suite/scenes/attenuation/point-d-0.json", "description": "point light at d = 0",
     "backend": "vulkan", "verdict": "Pass", "raw_verdict": "Pass", "expected_reason": "", "message": "",
     "metrics": {"compared_pixels": 4096, "masked_pixels": 10, "failing_pixels": 0, "non_finite_pixels": 0,
                 "max_failing_pixels": 0, "max_abs_error": 1.2e-6, "rmse": 3e-7, "tightness": 0.03, "worst": []},
     "frames": [{"frame": 0, "verdict": "Pass", "failing_pixels": 0, "max_abs_error": 1.2e-6, "tightness": 0.03,
                 "ideal_error": null, "popping_jump": null}],
     "popping_score": null,
     "timings_ms": {"reference": 12, "pipeline": 5, "draw": 3, "readback": 1, "compare": 1, "total": 25},
     "evidence": null},
    {"name": "attenuation.point-d-half-range.vulkan", "group": "attenuation", "scene": "point-d-half-range",
     "scene_file": "suite/scenes/attenuation/point-d-half-range.json",
     "description": "d < r & \"half\" range",
     "backend": "vulkan", "verdict": "Fail", "raw_verdict": "Fail", "expected_reason": "", "message": "",
     "metrics": {"compared_pixels": 4096, "masked_pixels": 10, "failing_pixels": 37, "non_finite_pixels": 0,
                 "max_failing_pixels": 0, "max_abs_error": 0.25, "rmse": 0.01, "tightness": 812.5,
                 "worst": [{"x": 1, "y": 2, "result": [0.5, 0.5, 0.5], "reference": [0.25, 0.25, 0.25],
                            "tolerance": [0.001, 0.001, 0.001]}]},
     "frames": [{"frame": 0, "verdict": "Fail", "failing_pixels": 37, "max_abs_error": 0.25, "tightness": 812.5,
                 "ideal_error": null, "popping_jump": null}],
     "popping_score": null,
     "timings_ms": {"reference": 14, "pipeline": 5, "draw": 3, "readback": 1, "compare": 2, "total": 1500},
     "evidence": {"frame": 0, "result_png": "evidence/attenuation.point-d-half-range.vulkan/result.png",
                  "reference_png": "evidence/attenuation.point-d-half-range.vulkan/reference.png",
                  "error_mask_png": "evidence/attenuation.point-d-half-range.vulkan/error-mask.png",
                  "viewer": "evidence/attenuation.point-d-half-range.vulkan/viewer.html",
                  "summary_json": "evidence/attenuation.point-d-half-range.vulkan/summary.json"}},
    {"name": "limits.popping-64.vulkan", "group": "limits", "scene": "popping-64",
     "scene_file": "suite/scenes/limits/popping-64.json", "description": "animated camera over 100 lights",
     "backend": "vulkan", "verdict": "QualityWarning", "raw_verdict": "QualityWarning", "expected_reason": "",
     "message": "popping score 0.4 above 0.25",
     "metrics": {"compared_pixels": 12288, "masked_pixels": 30, "failing_pixels": 0, "non_finite_pixels": 0,
                 "max_failing_pixels": 0, "max_abs_error": 2e-6, "rmse": 4e-7, "tightness": 0.05, "worst": []},
     "frames": [{"frame": 0, "verdict": "Pass", "failing_pixels": 0, "max_abs_error": 1e-6, "tightness": 0.03,
                 "ideal_error": 0.1, "popping_jump": null},
                {"frame": 1, "verdict": "Pass", "failing_pixels": 0, "max_abs_error": 2e-6, "tightness": 0.05,
                 "ideal_error": 0.5, "popping_jump": 0.4},
                {"frame": 2, "verdict": "Pass", "failing_pixels": 0, "max_abs_error": 1e-6, "tightness": 0.02,
                 "ideal_error": 0.45, "popping_jump": 0.05}],
     "popping_score": 0.4,
     "timings_ms": {"reference": 300, "pipeline": 5, "draw": 9, "readback": 3, "compare": 3, "total": 320},
     "evidence": null},
    {"name": "stability.far-1e6.vulkan", "group": "stability", "scene": "far-1e6",
     "scene_file": "suite/scenes/stability/far-1e6.json", "description": "the scene moved to 1e6",
     "backend": "vulkan", "verdict": "Crash", "raw_verdict": "Crash", "expected_reason": "",
     "message": "worker crashed: signal 11 <SIGSEGV> & \"core\"\nsecond line",
     "metrics": null, "frames": [], "popping_score": null,
     "timings_ms": {"reference": null, "pipeline": null, "draw": null, "readback": null, "compare": null, "total": 40},
     "evidence": null},
    {"name": "attenuation.point-d-0.gl-egl-softpipe", "group": "attenuation", "scene": "point-d-0",
     "scene_file": "suite/scenes/attenuation/point-d-0.json", "description": "point light at d = 0",
     "backend": "gl-egl-softpipe", "verdict": "Pass", "raw_verdict": "Pass", "expected_reason": "", "message": "",
     "metrics": {"compared_pixels": 4096, "masked_pixels": 10, "failing_pixels": 0, "non_finite_pixels": 0,
                 "max_failing_pixels": 0, "max_abs_error": 1e-6, "rmse": 3e-7, "tightness": 0.02, "worst": []},
     "frames": [], "popping_score": null,
     "timings_ms": {"reference": 0, "pipeline": 50, "draw": 30, "readback": 1, "compare": 1, "total": 82},
     "evidence": null},
    {"name": "attenuation.point-d-half-range.gl-egl-softpipe", "group": "attenuation", "scene": "point-d-half-range",
     "scene_file": "suite/scenes/attenuation/point-d-half-range.json", "description": "d < r & \"half\" range",
     "backend": "gl-egl-softpipe", "verdict": "ExpectedFail", "raw_verdict": "Fail",
     "expected_reason": "softpipe rounds <pow> & \"exp2\"", "message": "",
     "metrics": {"compared_pixels": 4096, "masked_pixels": 10, "failing_pixels": 3, "non_finite_pixels": 0,
                 "max_failing_pixels": 0, "max_abs_error": 0.002, "rmse": 1e-4, "tightness": 2.5, "worst": []},
     "frames": [], "popping_score": null,
     "timings_ms": {"reference": 0, "pipeline": 50, "draw": 30, "readback": 1, "compare": 1, "total": 82},
     "evidence": null},
    {"name": "limits.popping-64.gl-egl-softpipe", "group": "limits", "scene": "popping-64",
     "scene_file": "suite/scenes/limits/popping-64.json", "description": "animated camera over 100 lights",
     "backend": "gl-egl-softpipe", "verdict": "Timeout", "raw_verdict": "Timeout", "expected_reason": "",
     "message": "no result after 120 s",
     "metrics": null,
     "frames": [{"frame": 0, "verdict": "Pass", "failing_pixels": 0, "max_abs_error": 1e-6, "tightness": 0.03,
                 "ideal_error": 0.1, "popping_jump": null}],
     "popping_score": null,
     "timings_ms": {"reference": null, "pipeline": null, "draw": null, "readback": null, "compare": null,
                    "total": 120000},
     "evidence": null},
    {"name": "baked.legacy-falloff.gl-egl-softpipe", "group": "baked", "scene": "legacy-falloff",
     "scene_file": "suite/scenes/baked/legacy-falloff.json", "description": "legacy falloff against real time",
     "backend": "gl-egl-softpipe", "verdict": "UnexpectedPass", "raw_verdict": "Pass",
     "expected_reason": "softpipe lightmap filtering", "message": "",
     "metrics": {"compared_pixels": 4096, "masked_pixels": 0, "failing_pixels": 0, "non_finite_pixels": 0,
                 "max_failing_pixels": 0, "max_abs_error": 1e-6, "rmse": 3e-7, "tightness": 0.01, "worst": []},
     "frames": [], "popping_score": null,
     "timings_ms": {"reference": 10, "pipeline": 50, "draw": 30, "readback": 1, "compare": 1, "total": 92},
     "evidence": null},
    {"name": "deferred.ldr8.gl-egl-softpipe", "group": "deferred", "scene": "ldr8",
     "scene_file": "suite/scenes/deferred/ldr8.json", "description": "deferred, 8-bit log buffer",
     "backend": "gl-egl-softpipe", "verdict": "NotSupported", "raw_verdict": "NotSupported", "expected_reason": "",
     "message": "deferred path not implemented on gl-egl", "metrics": null, "frames": [], "popping_score": null,
     "timings_ms": {"reference": null, "pipeline": null, "draw": null, "readback": null, "compare": null, "total": 1},
     "evidence": null},
    {"name": "per-object.eleven lights#1.gl-egl-softpipe", "group": "per-object", "scene": "eleven lights#1",
     "scene_file": "suite/scenes/per-object/eleven lights#1.json", "description": "a file name with a space and #",
     "backend": "gl-egl-softpipe", "verdict": "Fail", "raw_verdict": "Fail", "expected_reason": "", "message": "",
     "metrics": {"compared_pixels": 4096, "masked_pixels": 12, "failing_pixels": 5, "non_finite_pixels": 1,
                 "max_failing_pixels": 2, "max_abs_error": null, "rmse": null, "tightness": null,
                 "tightness_is_infinite": true,
                 "worst": [{"x": 7, "y": 9, "result": [null, 0.5, 0.5], "reference": [0.5, 0.5, 0.5],
                            "tolerance": [0.001, 0.001, 0.001], "tolerance_scale": 2}]},
     "frames": [], "popping_score": null,
     "timings_ms": {"reference": 10, "pipeline": 50, "draw": 30, "readback": 1, "compare": 1, "total": 95},
     "evidence": {"frame": 0, "result_png": "evidence/per-object.eleven lights#1.gl-egl-softpipe/result.png",
                  "reference_png": "evidence/per-object.eleven lights#1.gl-egl-softpipe/reference.png",
                  "error_mask_png": "evidence/per-object.eleven lights#1.gl-egl-softpipe/error-mask.png",
                  "summary_json": null}}
  ],
  "mutants": [
    {"mutant": "unsquared-range", "what": "range attenuation not squared", "backend": "vulkan", "status": "killed",
     "killed_by": ["attenuation.point-d-half-range", "attenuation.point-d-0-8-range"],
     "evidence": {"test": "attenuation.point-d-half-range.vulkan",
                  "result_png": "mutants/unsquared-range.vulkan/result.png",
                  "reference_png": "mutants/unsquared-range.vulkan/reference.png",
                  "error_mask_png": "mutants/unsquared-range.vulkan/error-mask.png"}},
    {"mutant": "unsquared-range", "what": "range attenuation not squared", "backend": "gl-egl-softpipe",
     "status": "killed", "killed_by": ["attenuation.point-d-half-range"],
     "evidence": {"test": "attenuation.point-d-half-range.gl-egl-softpipe",
                  "result_png": "mutants/unsquared-range.gl-egl-softpipe/result.png",
                  "reference_png": "mutants/unsquared-range.gl-egl-softpipe/reference.png",
                  "error_mask_png": "mutants/unsquared-range.gl-egl-softpipe/error-mask.png"}},
    {"mutant": "distance-clamp-1e-4", "what": "distance clamped at 1e-4 <not 1e-6>", "backend": "vulkan",
     "status": "survived", "killed_by": [], "evidence": null},
    {"mutant": "distance-clamp-1e-4", "what": "distance clamped at 1e-4 <not 1e-6>", "backend": "gl-egl-softpipe",
     "status": "Crash", "killed_by": [], "evidence": null}
  ]
}
)json");
}

std::vector<std::string> samplePngPaths(const nlohmann::ordered_json& results) {
  std::vector<std::string> paths;
  const auto add = [&](const nlohmann::ordered_json& evidence) {
    if (!evidence.is_object()) return;
    for (const char* key : {"result_png", "reference_png", "error_mask_png"})
      if (evidence.contains(key) && evidence[key].is_string()) paths.push_back(evidence[key].get<std::string>());
  };
  for (const auto& test : results["tests"]) add(test["evidence"]);
  for (const auto& mutant : results["mutants"]) add(mutant["evidence"]);
  return paths;
}

}  // namespace reports::testing
