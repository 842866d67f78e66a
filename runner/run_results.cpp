#include "runner/run_results.h"

#include "baking/sha256.h"
#include "imaging/atomic_file.h"
#include "reports/csv_writer.h"
#include "reports/html_report.h"
#include "reports/junit_writer.h"
#include "results/result_rules.h"
#include "shaders/shader_variant.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <string>

namespace runner {

namespace fs = std::filesystem;

std::string scenesDigest(const std::vector<fs::path>& sceneFiles, const fs::path& root) {
  std::string all;
  for (const fs::path& file : sceneFiles) {
    std::ifstream in(file, std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    const std::string name = fs::relative(file, root).generic_string();
    all += std::to_string(name.size()) + ":" + name + std::to_string(bytes.size()) + ":" + bytes;
  }
  return baking::toHex(baking::sha256(all.data(), all.size()));
}

std::string backendCounts(const results::BackendRecord& backend, bool mutantsChecked) {
  std::string text;
  for (const comparison::Verdict verdict : comparison::kAllVerdicts)
    if (const auto it = backend.counts.find(verdict); it != backend.counts.end() && it->second > 0)
      text += ", " + std::to_string(it->second) + " " + std::string(comparison::verdictName(verdict));
  if (mutantsChecked)
    text += "; mutants: " + std::to_string(backend.mutantCounts.killed) + " killed, " +
            std::to_string(backend.mutantCounts.survived) + " survived";
  return text;
}

std::vector<results::AdmissibleRecord> describedAdmissibleRecords(const std::vector<results::TestRecord>& tests) {
  std::vector<results::AdmissibleRecord> records = results::admissibleRecords(tests);
  for (results::AdmissibleRecord& record : records)
    if (const auto variant = shaders::admissibleFromName(record.variant);
        variant && *variant != shaders::Admissible::None) {
      record.what = std::string(shaders::admissibleEntry(*variant).what);
      record.grant = std::string(shaders::admissibleEntry(*variant).grant);
    }
  return records;
}

std::vector<std::string> admissibleLines(const std::vector<results::AdmissibleRecord>& records) {
  std::vector<std::string> lines;
  std::vector<std::string> backends;
  for (const results::AdmissibleRecord& r : records)
    if (std::find(backends.begin(), backends.end(), r.backend) == backends.end()) backends.push_back(r.backend);
  for (const std::string& backend : backends) {
    int sound = 0, tests = 0;
    std::vector<std::string> others;
    for (const results::AdmissibleRecord& r : records) {
      if (r.backend != backend) continue;
      tests += r.tests;
      if (r.status == comparison::AdmissibleStatus::Sound) {
        ++sound;
        continue;
      }
      std::string line = "run: admissible: " + backend + ": " + r.variant + " " +
                         std::string(comparison::admissibleStatusName(r.status));
      for (std::size_t i = 0; i < r.failed.size() && i < 5; ++i) line += (i == 0 ? ": " : ", ") + r.failed[i];
      if (r.failed.size() > 5) line += " and " + std::to_string(r.failed.size() - 5) + " more";
      others.push_back(line);
    }
    lines.push_back("run: admissible: " + backend + ": " + std::to_string(sound) + " variant(s) sound over " +
                    std::to_string(tests) + " test(s)" + (others.empty() ? "" : ", " + std::to_string(others.size()) + " not"));
    lines.insert(lines.end(), others.begin(), others.end());
  }
  return lines;
}

void removeStaleRunOutputs(const fs::path& outDir) {
  for (const char* stale : {"evidence", "mutants", "budgets", "report"}) fs::remove_all(outDir / stale);
  for (const char* stale : {"results.json", "junit.xml", "results.csv", "failures.csv"}) fs::remove(outDir / stale);
  const fs::path logsDir = outDir / "logs";
  if (!fs::is_directory(logsDir)) return;
  std::vector<fs::path> stale;  // logs/<suffix>.retry-N.* and .part-K.*, which this run may not write
  for (const fs::directory_entry& entry : fs::directory_iterator(logsDir)) {
    const std::string name = entry.path().filename().string();
    if (name.find(".retry-") != std::string::npos || name.find(".part-") != std::string::npos)
      stale.push_back(entry.path());
  }
  for (const fs::path& file : stale) fs::remove(file);
}

void writeRunOutputs(const results::RunRecord& run, const fs::path& outDir) {
  reports::writeHtmlReport(run, outDir / "report");
  reports::writeJunit(run, outDir / "junit.xml");
  reports::writeRunCsvs(run, outDir);  // results.csv, failures.csv (deqp-runner's lists)
  imaging::writeFileAtomically(outDir / "results.json", run.toJson().dump(1) + "\n");
}

}  // namespace runner
