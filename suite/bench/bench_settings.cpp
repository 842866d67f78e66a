#include "suite/bench/bench_settings.h"

#include "app/exit_status.h"
#include "backends/backend.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>

namespace bench {
namespace {

using app::kExitBadInput;  // as the lightcts command (SPEC 8)

bool startsWith(std::string_view a, std::string_view prefix, std::string_view& value) {
  if (!a.starts_with(prefix)) return false;
  value = a.substr(prefix.size());
  return true;
}

// "a, b or c", for the messages that say what a flag accepts.
std::string oneOf(const std::vector<std::string>& names) {
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i)
    text += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  return text;
}

// The drivers the combination table names (llvmpipe, softpipe, swiftshader, zink), in table order.
std::vector<std::string> tableDrivers() {
  std::vector<std::string> drivers;
  for (const backends::BackendCombination& c : backends::backendCombinations())
    if (!c.driver.empty() && std::find(drivers.begin(), drivers.end(), c.driver) == drivers.end())
      drivers.push_back(c.driver);
  return drivers;
}

// The table's combination of this backend and driver; nullptr for a pair it
// does not have (a Mesa driver on Vulkan, swiftshader on GL).
const backends::BackendCombination* combinationOf(const std::string& backend, const std::string& driver) {
  return backends::findCombination(backend, driver);
}

// 0, or kExitBadInput with the reason on stderr.
int checkCombination(Settings& settings) {
  const std::vector<std::string>& backendNames = backends::specBackendNames();
  if (std::find(backendNames.begin(), backendNames.end(), settings.backend) == backendNames.end()) {
    std::fprintf(stderr, "render_bench: --backend must be %s, not '%s'\n", oneOf(backendNames).c_str(),
                 settings.backend.c_str());
    return kExitBadInput;
  }
  const std::vector<std::string> drivers = tableDrivers();
  if (!settings.driver.empty() && std::find(drivers.begin(), drivers.end(), settings.driver) == drivers.end()) {
    std::fprintf(stderr, "render_bench: --driver must be %s, not '%s'\n", oneOf(drivers).c_str(),
                 settings.driver.c_str());
    return kExitBadInput;
  }
  settings.combination = combinationOf(settings.backend, settings.driver);
  if (!settings.combination) {
    std::fprintf(stderr, "render_bench: --driver=%s is not a driver of %s (the combinations: %s)\n",
                 settings.driver.c_str(), settings.backend.c_str(), backends::combinationSuffixList().c_str());
    return kExitBadInput;
  }
  return 0;
}

}  // namespace

ParsedFlags parseFlags(int argc, char** argv, const std::filesystem::path& defaultScenes) {
  ParsedFlags parsed;
  Settings& settings = parsed.settings;
  settings.scenes = defaultScenes;
  for (int i = 0; i < argc; ++i) {
    const std::string_view a(argv[i]);
    std::string_view value;
    if (i > 0 && startsWith(a, "--backend=", value)) settings.backend = std::string(value);
    else if (i > 0 && startsWith(a, "--driver=", value)) settings.driver = std::string(value);
    else if (i > 0 && startsWith(a, "--scenes=", value)) settings.scenes = std::filesystem::path(value);
    else if (i > 0 && startsWith(a, "--ideal_cache=", value)) settings.idealCache = std::filesystem::path(value);
    else if (i > 0 && startsWith(a, "--error_cache=", value)) settings.errorCache = std::filesystem::path(value);
    else if (i > 0 && startsWith(a, "--peak_gflops=", value)) {
      char* end = nullptr;
      const std::string text(value);
      const double gflops = std::strtod(text.c_str(), &end);
      if (end == text.c_str() || *end != '\0' || !(gflops > 0)) {
        std::fprintf(stderr, "render_bench: --peak_gflops needs a positive number, not '%s'\n", text.c_str());
        parsed.usageError = kExitBadInput;
        return parsed;
      }
      settings.peakGflops = gflops;
    } else if (i > 0 && startsWith(a, "--mutant=", value)) {
      const std::optional<shaders::Mutant> mutant = shaders::mutantFromName(value);
      if (!mutant) {
        std::fprintf(stderr, "render_bench: --mutant: no mutant '%s' (shaders/shader_variant.h)\n",
                     std::string(value).c_str());
        parsed.usageError = kExitBadInput;
        return parsed;
      }
      settings.mutant = *mutant;
    } else if (i > 0 && (startsWith(a, "--cluster_tile=", value) || startsWith(a, "--cluster_slices=", value))) {
      const std::string text(value);
      char* end = nullptr;
      const long n = std::strtol(text.c_str(), &end, 10);
      if (end == text.c_str() || *end != '\0' || n < 1 || n > 4096) {
        std::fprintf(stderr, "render_bench: %.*s needs a whole number from 1 to 4096, not '%s'\n",
                     int(a.size() - value.size() - 1), a.data(), text.c_str());
        parsed.usageError = kExitBadInput;
        return parsed;
      }
      (startsWith(a, "--cluster_tile=", value) ? settings.clusterGrid.tileSize : settings.clusterGrid.depthSlices) =
          int(n);
    } else if (i > 0 && startsWith(a, "--field_size=", value)) {
      const std::string text(value);
      int width = 0, height = 0, used = 0;
      if (std::sscanf(text.c_str(), "%dx%d%n", &width, &height, &used) != 2 || used != int(text.size()) ||
          width < 16 || height < 16 || width > 4096 || height > 4096) {
        std::fprintf(stderr, "render_bench: --field_size is WxH, each from 16 to 4096, not '%s'\n", text.c_str());
        parsed.usageError = kExitBadInput;
        return parsed;
      }
      settings.fieldWidth = width;
      settings.fieldHeight = height;
    } else if (i > 0 && startsWith(a, "--uniform_reads=", value)) {
      if (value == "opaque") settings.constantUniformReads = false;
      else if (value == "constant") settings.constantUniformReads = true;
      else {
        std::fprintf(stderr, "render_bench: --uniform_reads is opaque or constant, not '%s'\n", std::string(value).c_str());
        parsed.usageError = kExitBadInput;
        return parsed;
      }
    } else if (i > 0 && startsWith(a, "--time_source=", value)) {
      if (value == "auto") settings.timeSource = TimeSource::Calibrated;
      else if (value == "device") settings.timeSource = TimeSource::Device;
      else if (value == "wall") settings.timeSource = TimeSource::Wall;
      else {
        std::fprintf(stderr, "render_bench: --time_source is auto, device or wall, not '%s'\n", std::string(value).c_str());
        parsed.usageError = kExitBadInput;
        return parsed;
      }
    } else if (i > 0 && startsWith(a, "--set=", value)) {
      if (value == "auto") settings.frameSet = Settings::FrameSet::Measured;
      else if (value == "full") settings.frameSet = Settings::FrameSet::Full;
      else if (value == "scaled") settings.frameSet = Settings::FrameSet::Scaled;
      else {
        std::fprintf(stderr, "render_bench: --set is auto, full or scaled, not '%s'\n", std::string(value).c_str());
        parsed.usageError = kExitBadInput;
        return parsed;
      }
    } else if (i > 0 && a == "--quick") settings.quick = true;
    else if (i > 0 && a == "--suite_scenes") settings.suiteScenes = true;
    else parsed.rest.push_back(argv[i]);
  }
  if (settings.suiteScenes) settings.errorCache.clear();
  parsed.usageError = checkCombination(settings);
  return parsed;
}

}  // namespace bench
