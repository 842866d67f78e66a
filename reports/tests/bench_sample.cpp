#include "reports/tests/bench_sample.h"

#include <cmath>

#include <string>
#include <vector>

namespace reports::testing {
namespace {

using Json = nlohmann::ordered_json;

// One repetition entry as Google Benchmark writes it; counters are extra keys.
Json repetition(const std::string& name, int index, int count, double realTime, const char* unit,
                const Json& counters) {
  Json e = {{"name", name},           {"family_index", 0},     {"per_family_instance_index", 0},
            {"run_name", name},       {"run_type", "iteration"}, {"repetitions", count},
            {"repetition_index", index}, {"threads", 1},       {"iterations", 10},
            {"real_time", realTime},  {"cpu_time", realTime / 2}, {"time_unit", unit}};
  for (auto it = counters.begin(); it != counters.end(); ++it) e[it.key()] = it.value();
  return e;
}

Json aggregate(const std::string& name, const std::string& which, int count, double realTime, const char* unit,
               const Json& counters) {
  Json e = {{"name", name + "_" + which}, {"family_index", 0}, {"per_family_instance_index", 0},
            {"run_name", name},           {"run_type", "aggregate"}, {"repetitions", count},
            {"threads", 1},               {"aggregate_name", which}, {"aggregate_unit", "time"},
            {"iterations", count},        {"real_time", realTime}, {"cpu_time", realTime / 2},
            {"time_unit", unit}};
  for (auto it = counters.begin(); it != counters.end(); ++it) e[it.key()] = it.value();
  return e;
}

// Repetitions plus Google Benchmark's median, mean and stddev aggregates.
void withAggregates(Json& into, const std::string& name, const std::vector<double>& times, double median,
                    double mean, double stddev, const Json& counters) {
  const int n = int(times.size());
  for (int i = 0; i < n; ++i) into.push_back(repetition(name, i, n, times[std::size_t(i)], "ms", counters));
  into.push_back(aggregate(name, "mean", n, mean, "ms", counters));
  into.push_back(aggregate(name, "median", n, median, "ms", counters));
  into.push_back(aggregate(name, "stddev", n, stddev, "ms", Json::object()));
}

void repetitionsOnly(Json& into, const std::string& name, const std::vector<double>& times, const char* unit,
                     const Json& counters) {
  const int n = int(times.size());
  for (int i = 0; i < n; ++i) into.push_back(repetition(name, i, n, times[std::size_t(i)], unit, counters));
}

Json frameCounters(double errRmse, double errMax, double limitMs, bool device, double ms) {
  Json c = {{"wall_ms", ms * 1.1}, {"pixels", 921600}, {"lights", 64}, {"lights_per_pixel", 12.5},
            {"pixels_per_s", 921600 / (ms / 1000)}, {"err_rmse", errRmse}, {"err_max_abs", errMax},
            {"err_psnr_db", 60.5}, {"flops_per_pixel_light", 30}, {"limit_ms", limitMs}};
  if (device) c["device_ms"] = ms;
  return c;
}

}  // namespace

Json sampleBench() {
  Json vulkan = Json::array();
  const std::string synth = "/lights64-1280x720/";
  // vulkan: manual (device) time, 5 repetitions and aggregates.
  withAggregates(vulkan, "frame/vulkan" + synth + "all-lights/manual_time", {10.2, 9.8, 10.0, 10.5, 9.9}, 10.0,
                 10.08, 0.27, frameCounters(1e-4, 2e-3, 0.5, true, 10.0));
  withAggregates(vulkan, "frame/vulkan" + synth + "per-object/manual_time", {6.1, 5.9, 6.0, 6.3, 5.8}, 6.0, 6.02,
                 0.19, frameCounters(5e-3, 4e-2, 0.1, true, 6.0));
  withAggregates(vulkan, "frame/vulkan" + synth + "legacy-4+4/manual_time", {3.0, 3.1, 2.9, 3.05, 2.95}, 3.0, 3.0,
                 0.08, frameCounters(2e-2, 0.2, 0.06, true, 3.0));
  withAggregates(vulkan, "frame/vulkan" + synth + "full-shader/manual_time", {12, 12.5, 11.8, 12.2, 11.9}, 12.0,
                 12.08, 0.28, frameCounters(1e-4, 2e-3, 0.5, true, 12.0));
  for (int lights : {1, 4, 16, 64, 256}) {
    const double t = 0.5 + 0.1 * lights;
    // An exact line in the pixel-lights (the two-term fit's model): a = 0.5 ms
    // over 921600 pixels, b = 0.1 ms over 921600 pixel-lights.
    repetitionsOnly(vulkan, "frame/vulkan/curve-lights/all-lights/" + std::to_string(lights) + "/manual_time",
                    {t * 0.98, t, t * 1.03}, "ms",
                    {{"lights", lights}, {"pixels", 921600}, {"lights_per_pixel", lights}});
    repetitionsOnly(vulkan, "frame/vulkan/curve-lights/per-object/" + std::to_string(lights) + "/manual_time",
                    {t * 0.5, t * 0.52, t * 0.55}, "ms", {{"lights", lights}});
  }
  for (const char* res : {"320x180", "640x360", "1280x720"})
    repetitionsOnly(vulkan, std::string("frame/vulkan/curve-resolution/all-lights/") + res + "/manual_time",
                    {1.0, 1.1, 1.2}, "ms", Json::object());
  for (int objects : {1, 10, 100})
    repetitionsOnly(vulkan, "frame/vulkan/curve-objects/all-lights/" + std::to_string(objects) + "/manual_time",
                    {0.2 * objects, 0.21 * objects, 0.22 * objects}, "ms", Json::object());
  withAggregates(vulkan, "frame_readback/vulkan/attenuation.point-d-zero/all-lights/real_time",
                 {1.5, 1.6, 1.4, 1.5, 1.7}, 1.5, 1.54, 0.11, {{"wall_ms", 1.5}});
  vulkan.push_back({{"name", "pipeline/vulkan/attenuation.point-d-zero/all-lights/manual_time"},
                    {"run_name", "pipeline/vulkan/attenuation.point-d-zero/all-lights/manual_time"},
                    {"run_type", "iteration"}, {"repetitions", 1}, {"repetition_index", 0}, {"threads", 1},
                    {"iterations", 0}, {"real_time", 0}, {"cpu_time", 0}, {"time_unit", "ms"},
                    {"error_occurred", true}, {"error_message", "compile <failed> & \"x\""}});

  // gl-egl: wall time in microseconds, 3 repetitions, no aggregates.
  Json gl = Json::array();
  repetitionsOnly(gl, "frame/gl-egl" + synth + "all-lights", {20000, 21000, 19500}, "us",
                  frameCounters(5e-5, 1e-3, 0.5, false, 20.0));
  repetitionsOnly(gl, "frame/gl-egl" + synth + "per-object", {8000, 8100, 7900}, "us",
                  frameCounters(8e-3, 5e-2, 0.1, false, 8.0));
  repetitionsOnly(gl, "frame/gl-egl" + synth + "legacy-4+4", {2500, 2600, 2400}, "us",
                  frameCounters(3e-2, 0.3, 0.06, false, 2.5));
  for (int lights : {1, 4, 16, 64, 256})
    repetitionsOnly(gl, "frame/gl-egl/curve-lights/all-lights/" + std::to_string(lights),
                    {1000.0 + 300 * lights, 1010.0 + 300 * lights, 990.0 + 300 * lights}, "us", Json::object());

  // CPU preparation: aggregates only (--benchmark_report_aggregates_only), with complexity fits.
  Json prepare = Json::array();
  for (int n : {10, 100, 1000, 10000, 100000}) {
    const std::string name = "prepare/cpu/curve-lights/all-lights/" + std::to_string(n);
    prepare.push_back(aggregate(name, "median", 5, 0.02 * n, "us", Json::object()));
  }
  prepare.push_back({{"name", "prepare/cpu/curve-lights/all-lights_BigO"},
                     {"run_name", "prepare/cpu/curve-lights/all-lights"}, {"run_type", "aggregate"},
                     {"repetitions", 5}, {"threads", 1}, {"aggregate_name", "BigO"}, {"aggregate_unit", "time"},
                     {"cpu_coefficient", 0.01}, {"real_coefficient", 0.02}, {"big_o", "N"}, {"time_unit", "us"}});
  prepare.push_back({{"name", "prepare/cpu/curve-lights/all-lights_RMS"},
                     {"run_name", "prepare/cpu/curve-lights/all-lights"}, {"run_type", "aggregate"},
                     {"repetitions", 5}, {"threads", 1}, {"aggregate_name", "RMS"},
                     {"aggregate_unit", "percentage"}, {"rms", 0.031}});
  for (int n : {10, 100, 1000, 10000}) {
    const std::string name = "prepare/cpu/curve-objects/per-object/" + std::to_string(n);
    prepare.push_back(aggregate(name, "median", 5, 0.5 * n, "ns", Json::object()));
    prepare.push_back(aggregate(name, "min", 5, 0.45 * n, "ns", Json::object()));  // ComputeStatistics
    prepare.push_back(aggregate(name, "max", 5, 0.6 * n, "ns", Json::object()));
  }
  prepare.push_back({{"name", "prepare/cpu/curve-objects/per-object_BigO"},
                     {"run_name", "prepare/cpu/curve-objects/per-object"}, {"run_type", "aggregate"},
                     {"aggregate_name", "BigO"}, {"real_coefficient", 0.15}, {"big_o", "NlgN"},
                     {"time_unit", "ns"}});
  prepare.push_back({{"name", "prepare/cpu/curve-objects/per-object_RMS"},
                     {"run_name", "prepare/cpu/curve-objects/per-object"}, {"run_type", "aggregate"},
                     {"aggregate_name", "RMS"}, {"rms", 0.12}});
  prepare.push_back(aggregate("prepare/cpu/lights64-1280x720/all-lights", "median", 5, 35.0, "us", Json::object()));

  Json bench = {
      {"format", "lightcts-bench"}, {"version", 1}, {"lightcts_revision", "v0.2-7-gdeadbee"},
      {"started_utc", "2026-12-01T16:00:00Z"}, {"duration_s", 420.5},
      {"command", "lightcts bench --out out/bench"},
      {"machine", {{"hostname", "ci-1"}, {"cpu", "Test CPU <8 cores>"}, {"cores", 2}, {"os", "Debian 12"}}},
      {"peak", {{"gflops", 38.4}, {"cores", 2}, {"kernel", "8 independent FMA chains"}, {"median_of", 5}}},
      {"backends",
       {{{"backend", "vulkan"}, {"status", "ran"}, {"message", ""},
         {"device", {{"name", "llvmpipe (LLVM 15.0.6, 256 bits) <b>"}, {"driver", "llvmpipe"},
                     {"driver_version", "Mesa 22.3.6"}, {"api_version", "1.3.230"}}},
         {"context", {{"host_name", "ci-1"}, {"num_cpus", 2}, {"library_build_type", "release"}}},
         {"benchmarks", vulkan}},
        {{"backend", "gl-egl"}, {"status", "ran"}, {"message", ""},
         {"device", {{"name", "llvmpipe (LLVM 15.0.6, 256 bits)"}, {"driver", "llvmpipe"},
                     {"driver_version", "Mesa 22.3.6"}, {"api_version", "4.5"}}},
         {"context", {{"host_name", "ci-1"}}},
         {"benchmarks", gl}},
        {{"backend", "gl-osmesa"}, {"status", "NotSupported"},
         {"message", "libOSMesa.so.8 <not found> & \"quoted\""}, {"device", nullptr},
         {"context", nullptr}, {"benchmarks", Json::array()}}}},
      {"prepare", {{"context", {{"host_name", "ci-1"}}}, {"benchmarks", prepare}}}};
  return bench;
}

Json crowdedBench() {
  Json vulkan = Json::array();
  const auto frame = [&vulkan](const std::string& scene, const std::string& mode, double ms, double error) {
    repetitionsOnly(vulkan, "frame/vulkan/" + scene + "/" + mode + "/manual_time", {ms * 0.99, ms, ms * 1.02}, "ms",
                    frameCounters(error, error * 10, 0.5, true, ms));
  };
  const char* filters[] = {"hard", "bilinear", "tent3x3"};
  const int sizes[] = {256, 512, 1024, 2048, 4096};
  for (int i = 0; i < 30; ++i) {
    const std::string mode = i < 15 ? std::string("shadows-") + filters[i % 3] + "-" + std::to_string(sizes[i / 3])
                                    : "all-lights-variant-" + std::to_string(i);
    frame("lights64-1280x720", mode, std::pow(10.0, 2.0 * i / 29.0), 0.01);
  }
  for (const char* mode : {"all-lights", "clustered", "per-object", "full-shader", "specular", "specular-full-shader",
                           "per-object-specular", "cookie-lights"})
    frame("lights64-1280x720", mode, 5.0, 1e-5);
  for (int i = 0; i < 14; ++i)
    frame("lights64-320x180", std::string("shadows-") + filters[i % 3] + "-" + std::to_string(sizes[i % 5]),
          20.0 + 0.7 * i, 0.0095 + 0.0001 * i);
  for (const char* mode : {"all-lights", "clustered", "per-object"}) frame("lights64-320x180", mode, 4.0, 1.2e-5);
  return {{"format", "lightcts-bench"}, {"version", 1}, {"lightcts_revision", "crowded"},
          {"started_utc", "2026-12-01T16:00:00Z"}, {"duration_s", 1.0}, {"command", "bench_tool crowded"},
          {"machine", {{"hostname", "ci-1"}, {"cpu", "Test CPU"}, {"cores", 2}, {"os", "Debian 12"}}},
          {"backends",
           {{{"backend", "vulkan"}, {"status", "ran"}, {"message", ""},
             {"device", {{"name", "llvmpipe"}, {"driver", "llvmpipe"}, {"driver_version", "Mesa 22.3.6"},
                         {"api_version", "1.3.230"}}},
             {"context", {{"host_name", "ci-1"}}},
             {"benchmarks", vulkan}}}}};
}

Json plainBenchmarkFile(const std::vector<std::pair<std::string, std::vector<double>>>& runs) {
  Json benchmarks = Json::array();
  for (const auto& [name, times] : runs) repetitionsOnly(benchmarks, name, times, "ms", Json::object());
  return {{"context", {{"host_name", "test"}}}, {"benchmarks", benchmarks}};
}

}  // namespace reports::testing
