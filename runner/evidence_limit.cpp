#include "runner/evidence_limit.h"

#include "comparison/verdict.h"

#include <vector>

namespace runner {

long long limitEvidenceImages(std::vector<results::TestRecord>& tests, const std::filesystem::path& outDir, int limit) {
  namespace fs = std::filesystem;
  std::vector<results::TestRecord*> failures, others;
  for (results::TestRecord& test : tests) {
    if (!test.evidence) continue;
    (comparison::isRunFailure(test.verdict) ? failures : others).push_back(&test);
  }
  failures.insert(failures.end(), others.begin(), others.end());
  long long dropped = 0;
  for (std::size_t i = std::size_t(limit); i < failures.size(); ++i) {
    results::EvidenceRecord& evidence = *failures[i]->evidence;
    const std::string summary = evidence.summaryJson;
    const fs::path folder = (outDir / summary).lexically_normal().parent_path();
    // Only ever a test's own folder, evidence/<test>/, whatever the record says.
    const bool ownFolder = !summary.empty() && folder.parent_path() == (outDir / "evidence").lexically_normal();
    std::error_code ignored;
    std::vector<fs::path> images;  // listed first: no removal while the folder is being read
    if (ownFolder && fs::is_directory(folder))
      for (const fs::directory_entry& entry : fs::directory_iterator(folder, ignored))
        if (entry.path().filename() != "summary.json") images.push_back(entry.path());
    for (const fs::path& image : images) fs::remove_all(image, ignored);
    results::EvidenceRecord numbersOnly;  // its images are gone: nothing may link to them
    numbersOnly.frame = evidence.frame;
    numbersOnly.summaryJson = summary;
    numbersOnly.imagesKept = false;
    numbersOnly.test = evidence.test;
    evidence = numbersOnly;
    ++dropped;
  }
  return dropped;
}

}  // namespace runner
