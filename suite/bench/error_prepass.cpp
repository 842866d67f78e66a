#include "suite/bench/error_prepass.h"

#include <algorithm>
#include <exception>
#include <future>
#include <map>
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
  std::map<std::string, std::size_t> inFlight;                // content key -> index in pending
  std::vector<std::string> contents;                          // per pending: its content key
  std::vector<std::pair<std::string, std::size_t>> sharing;  // error key -> the pending it equals
  // The frames first, the selected ones only: the lightmap modes' bakes are
  // timed (bake_ms), so nothing else runs yet.
  std::vector<const BenchFrame*> frames;
  for (const ErrorCandidate& candidate : candidates) {
    frames.push_back(nullptr);
    if (!filterSelects(filter, candidate.name)) continue;
    try {
      frames.back() = &candidate.bench->get();
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
      backends::Backend& backend = run.backendFor(bench);
      backend.preparePipeline(bench.frame);
      backend.draw(bench.frame);
      run.lastDrawn[&backend] = &bench;
      imaging::Image image = backend.readback();
      // A frame read back bit for bit like an earlier one (here or in another
      // frame process of the run) has its error already, or soon.
      const std::string content = RunState::contentKey(bench.spec.referenceKey, image);
      if (const std::optional<ImageError> known = run.errorByContent(content)) {
        run.errors.emplace(key, *known);
        continue;
      }
      if (const auto same = inFlight.find(content); same != inFlight.end()) {
        sharing.emplace_back(key, same->second);
        queued.insert(key);
        continue;
      }
      // The ideal only now: a known error needs none (--error_cache).
      const imaging::Image& ideal = run.idealFor(bench);  // std::map: stays where it is
      inFlight.emplace(content, pending.size());
      contents.push_back(content);
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
        inFlight.erase(content);
        contents.pop_back();
        throw;
      }
      queued.insert(key);
    } catch (const std::exception&) {
      // The benchmark draws it again and reports the failure as its own.
    }
  }
  std::vector<std::optional<ImageError>> results;
  for (std::size_t p = 0; p < pending.size(); ++p) {
    results.push_back(pending[p].second.get());
    if (!results.back()) continue;
    run.errors.emplace(pending[p].first, *results.back());
    run.keepErrorByContent(contents[p], *results.back());
  }
  for (const auto& [key, p] : sharing)
    if (results[p]) run.errors.emplace(key, *results[p]);
}

}  // namespace bench
