#include "suite/bench/error_prepass.h"

#include <algorithm>
#include <exception>
#include <future>
#include <optional>
#include <regex>
#include <semaphore>
#include <set>
#include <thread>
#include <utility>

namespace bench {

bool filterSelects(const std::string& filter, const std::string& name) {
  if (filter.empty() || filter == "all") return true;
  const bool negated = filter.front() == '-';
  try {
    // Google Benchmark compiles the filter as a POSIX extended expression.
    const std::regex pattern(negated ? filter.substr(1) : filter, std::regex::extended);
    const bool found = std::regex_search(name, pattern) || std::regex_search(name + "/", pattern);
    return found != negated;
  } catch (const std::regex_error&) {
    return true;  // Google Benchmark will say what is wrong with it; computing more is harmless
  }
}

void precomputeErrors(RunState& run, const std::vector<ErrorCandidate>& candidates, const std::string& filter) {
  const int workers = int(std::max(1u, std::thread::hardware_concurrency()));
  std::counting_semaphore<> slots(workers);  // images waiting for or in compare_Yee, at most one per core
  std::vector<std::pair<std::string, std::future<std::optional<ImageError>>>> pending;
  std::set<std::string> queued;
  // The lazy frames first: their bakes are timed (bake_ms), so nothing else runs yet.
  std::vector<std::shared_ptr<const BenchFrame>> frames;
  for (const ErrorCandidate& candidate : candidates) {
    frames.push_back(candidate.bench);
    if (frames.back() || !candidate.made || !filterSelects(filter, candidate.name)) continue;
    try {
      if (!*candidate.made) *candidate.made = candidate.make();
      frames.back() = *candidate.made;
    } catch (const std::exception&) {
      // its benchmark makes it again and reports the failure
    }
  }
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    if (!frames[c]) continue;
    const ErrorCandidate& candidate = candidates[c];
    const BenchFrame& bench = *frames[c];
    const std::string& key = bench.spec.errorKey;
    if (bench.spec.referenceKey.empty() || run.errors.count(key) || queued.count(key) ||
        !filterSelects(filter, candidate.name))
      continue;
    try {
      const imaging::Image& ideal = run.idealFor(bench);  // std::map: stays where it is
      backends::Backend& backend = run.backendFor(bench);
      backend.preparePipeline(bench.frame);
      backend.draw(bench.frame);
      run.lastDrawn[&backend] = &bench;
      imaging::Image image = backend.readback();
      slots.acquire();
      try {
        pending.emplace_back(key, std::async(std::launch::async, [&slots, &ideal, image = std::move(image)] {
                               std::optional<ImageError> error;
                               try {
                                 error = compareToIdeal(image, ideal);
                               } catch (const std::exception&) {
                                 // the benchmark computes it again and reports why
                               }
                               slots.release();
                               return error;
                             }));
      } catch (...) {
        slots.release();
        throw;
      }
      queued.insert(key);
    } catch (const std::exception&) {
      // The benchmark draws it again and reports the failure as its own.
    }
  }
  for (auto& [key, future] : pending)
    if (std::optional<ImageError> error = future.get()) run.errors.emplace(key, *error);
}

}  // namespace bench
