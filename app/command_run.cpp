// `lightcts run` (SPEC 8), the hidden `lightcts worker` it starts, and
// `lightcts merge` of its shards (docs/ci.md).
#include "app/commands.h"
#include "app/exit_status.h"
#include "app/scene_input.h"
#include "conformance/reference_cache.h"
#include "imaging/image_codec_loader.h"
#include "runner/suite_worker.h"

#include <filesystem>
#include <fstream>
#include <ostream>
#include <stdexcept>

#include <unistd.h>

namespace app {

int runSuiteCommand(const runner::RunOptions& options, std::ostream& out, std::ostream& err) {
  return guardCommand(err, [&] {
    try {
      // The workers' evidence and the report are images: a missing module
      // stops the run before any worker starts.
      if (!options.listOnly) imaging::requireImageModule();
      return runner::runSuite(options, out, err);
    } catch (const std::invalid_argument& e) {
      throw InputError(e.what());  // unknown backend or mutant, bad --timeout
    }
  });
}

int runMergeCommand(const runner::MergeOptions& options, std::ostream& out, std::ostream& err) {
  return guardCommand(err, [&] {
    try {
      imaging::requireImageModule();  // the merged report's images
      return runner::mergeRuns(options, out);
    } catch (const runner::MergeRefused& e) {
      throw InputError(std::string("merge: ") + e.what());
    }
  });
}

bool stdoutIsTerminal() { return ::isatty(STDOUT_FILENO) == 1; }

std::string referenceCacheDirectory() { return conformance::defaultReferenceCacheDirectory().string(); }

// Beside the references: $LIGHTCTS_CACHE_DIR/bench-errors (docs/bench-format.md).
std::string benchErrorCacheDirectory() {
  const std::filesystem::path references = conformance::defaultReferenceCacheDirectory();
  return references.empty() ? std::string() : (references.parent_path() / "bench-errors").string();
}

bool parseShardArgument(const std::string& text, runner::RunOptions& options, std::ostream& err) {
  try {
    options.shard = runner::parseShard(text);
    return true;
  } catch (const std::invalid_argument& e) {
    err << "lightcts: run: " << e.what() << "\n";
    return false;
  }
}

int runWorkerCommand(const std::string& planFile, int start, std::ostream& out, std::ostream& err) {
  return guardCommand(err, [&] {
    std::ifstream in(planFile);
    if (!in) throw InputError("cannot read worker plan " + planFile);
    runner::WorkerPlan plan;
    try {
      plan = runner::planFromJson(nlohmann::json::parse(in));
    } catch (const nlohmann::json::exception& e) {
      throw InputError("worker plan " + planFile + ": " + e.what());
    } catch (const std::invalid_argument& e) {
      throw InputError("worker plan " + planFile + ": " + e.what());
    }
    return runner::runWorker(plan, start, out);
  });
}

}  // namespace app
