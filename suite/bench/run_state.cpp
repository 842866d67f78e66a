#include "suite/bench/run_state.h"

#include "reference/reference_renderer.h"

#include <cstdlib>
#include <system_error>
#include <unistd.h>

namespace bench {

namespace fs = std::filesystem;

backends::Backend& RunState::backendFor(const BenchFrame& bench) {
  if (!bench.spec.fullShader) return *specialised;
  if (!full) {
    backends::BackendOptions fullOptions = options;
    fullOptions.variant.specialised = false;
    full = entry->create(fullOptions);
  }
  return *full;
}

const imaging::Image& RunState::idealFor(const BenchFrame& bench) {
  const BenchFrameSpec& spec = bench.spec;
  auto it = ideal.find(spec.referenceKey);
  if (it == ideal.end()) {
    const reference::ReferenceOptions idealOptions{.ideal = true};
    if (spec.referencePrepared) {
      const reference::ReferenceRenderer renderer(spec.referencePrepared);
      const lighting::Frame frame = lighting::prepareFrame(spec.referencePrepared, bench.frame.index);
      it = ideal.emplace(spec.referenceKey, renderer.render(frame, idealOptions).value).first;
    } else {
      const reference::ReferenceRenderer renderer(spec.prepared);
      it = ideal.emplace(spec.referenceKey, renderer.render(bench.frame, idealOptions).value).first;
    }
  }
  return it->second;
}

const ImageError& RunState::errorFor(const BenchFrame& bench, const std::function<imaging::Image()>& readback) {
  auto it = errors.find(bench.spec.errorKey);
  if (it == errors.end()) it = errors.emplace(bench.spec.errorKey, compareToIdeal(readback(), idealFor(bench))).first;
  return it->second;
}

void useFreshPipelineCache(RunState& run) {
  // Appended, not `"literal" + std::string&&`: GCC 12 warns falsely (-Wrestrict) on that.
  const std::string name = std::string("lightcts-render-bench-cache-").append(std::to_string(::getpid()));
  run.cacheDir = fs::temp_directory_path() / name;
  fs::remove_all(run.cacheDir);
  fs::create_directories(run.cacheDir);
  ::setenv("LIGHTCTS_CACHE_DIR", run.cacheDir.c_str(), 1);
}

void emptyPipelineCache(const RunState& run) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(run.cacheDir, ec)) fs::remove_all(entry.path(), ec);
}

}  // namespace bench
