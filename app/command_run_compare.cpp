// `lightcts run compare OLD NEW [--out DIR]` (docs/cli.md): what
// changed between two runs' results.json. Both files are read and checked
// before anything is written, so bad input (exit 2) leaves no page behind.
#include "app/commands.h"
#include "app/exit_status.h"
#include "app/scene_input.h"
#include "reports/run_compare.h"
#include "results/results_file.h"

#include <ostream>
#include <stdexcept>

namespace app {
namespace {

// The records' reader refuses what a comparison cannot trust (a key missing:
// the message names it), before anything is written.
results::RunRecord readRun(const std::string& path) {
  try {
    return results::readResultsFile(path);
  } catch (const results::ResultsFileError& e) {
    throw InputError(std::string("run compare: ") + e.what());
  }
}

}  // namespace

int runRunCompareCommand(const std::string& oldFile, const std::string& newFile, const std::string& outDir,
                         std::ostream& out, std::ostream& err) {
  return guardCommand(err, [&] {
    const results::RunRecord oldRun = readRun(oldFile);
    const results::RunRecord newRun = readRun(newFile);
    const reports::RunComparison comparison = reports::compareRuns(oldRun, newRun);
    reports::printRunComparison(comparison, oldFile, newFile, out);
    if (!outDir.empty()) {
      makeOutputDirectory(outDir);
      const auto page = reports::writeRunComparisonHtml(comparison, oldRun, newRun, oldFile, newFile, outDir);
      out << "run compare: page in " << page.string() << "\n";
    }
    return comparison.regressions.empty() ? kExitSuccess : kExitConformanceFailure;
  });
}

}  // namespace app
