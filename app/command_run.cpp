// `lightcts run` (SPEC 8) and the hidden `lightcts worker` it starts.
#include "app/commands.h"
#include "app/exit_status.h"
#include "app/scene_input.h"
#include "runner/suite_worker.h"

#include <fstream>
#include <ostream>
#include <stdexcept>

namespace app {

int runSuiteCommand(const runner::RunOptions& options, std::ostream& out, std::ostream& err) {
  return guardCommand(err, [&] {
    try {
      return runner::runSuite(options, out, err);
    } catch (const std::invalid_argument& e) {
      throw InputError(e.what());  // unknown backend or mutant, bad --timeout
    }
  });
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
    }
    return runner::runWorker(plan, start, out);
  });
}

}  // namespace app
