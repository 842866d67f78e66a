// `lightcts run compare OLD NEW [--out DIR]` (docs/cli.md): what
// changed between two runs' results.json. Both files are read and checked
// before anything is written, so bad input (exit 2) leaves no page behind.
#include "app/commands.h"
#include "app/exit_status.h"
#include "app/scene_input.h"
#include "reports/run_compare.h"
#include "results/results_file.h"

#include <fstream>
#include <ostream>
#include <stdexcept>

namespace app {
namespace {

reports::Json readResults(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError("run compare: cannot read " + path);
  reports::Json results;
  try {
    results = reports::Json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw InputError("run compare: " + path + ": not JSON: " + e.what());
  }
  try {
    // The records' reader refuses what a comparison cannot trust (a key
    // missing: the message names it); the comparison reads the words as written.
    results::checkedRunRecord(results, path);
  } catch (const std::invalid_argument& e) {
    throw InputError(std::string("run compare: ") + e.what());
  }
  return results;
}

}  // namespace

int runRunCompareCommand(const std::string& oldFile, const std::string& newFile, const std::string& outDir,
                         std::ostream& out, std::ostream& err) {
  return guardCommand(err, [&] {
    const reports::Json oldResults = readResults(oldFile);
    const reports::Json newResults = readResults(newFile);
    const reports::RunComparison comparison = reports::compareRuns(oldResults, newResults);
    reports::printRunComparison(comparison, oldFile, newFile, out);
    if (!outDir.empty()) {
      makeOutputDirectory(outDir);
      const auto page = reports::writeRunComparisonHtml(comparison, oldResults, newResults, oldFile, newFile, outDir);
      out << "run compare: page in " << page.string() << "\n";
    }
    return comparison.regressions.empty() ? kExitSuccess : kExitConformanceFailure;
  });
}

}  // namespace app
