#include "runner/run_plan.h"

#include "baking/sha256.h"
#include "results/results_file.h"

#include <algorithm>
#include <charconv>
#include <numeric>
#include <stdexcept>
#include <utility>

namespace runner {
namespace {

bool parseInt(std::string_view text, int& value) {
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return error == std::errc() && end == text.data() + text.size();
}

}  // namespace

ShardSpec parseShard(const std::string& text) {
  const std::size_t slash = text.find('/');
  ShardSpec shard;
  if (slash == std::string::npos || !parseInt(std::string_view(text).substr(0, slash), shard.index) ||
      !parseInt(std::string_view(text).substr(slash + 1), shard.total) || shard.total < 1 || shard.index < 1 ||
      shard.index > shard.total)
    throw std::invalid_argument("--shard '" + text + "': expected I/N with 1 <= I <= N (e.g. 2/3)");
  return shard;
}

Timings loadTimings(const std::string& resultsFile) {
  results::RunRecord run;
  try {
    run = results::readResultsFile(resultsFile);
  } catch (const results::ResultsFileError& e) {
    throw std::invalid_argument(std::string("--timings ") + e.what());
  }
  Timings timings;
  // A test without a total (a crash, or a file without one) is one the
  // timings do not know: it costs the mean of the others (unitCosts).
  for (const results::TestRecord& test : run.tests)
    if (test.timingsMs && test.timingsMs->total > 0)
      timings[test.name] = {test.timingsMs->total, test.timingsMs->reference};
  return timings;
}

std::vector<double> unitCosts(const std::vector<RunUnit>& units, const std::optional<Timings>& timings) {
  std::vector<double> costs;
  if (!timings) {
    for (const RunUnit& unit : units) costs.push_back(double(unit.tasks.size()));
    return costs;
  }
  auto costOf = [](const RunUnit& unit, const TestTiming& t) {
    double cost = 0;
    for (const WorkerTask& task : unit.tasks)
      cost += task.isModelTest() ? t.totalMs : std::max(t.totalMs - t.referenceMs, 0.0);
    return cost;
  };
  double knownSum = 0;
  int known = 0;
  for (const RunUnit& unit : units)
    if (const auto it = timings->find(unit.test); it != timings->end()) {
      knownSum += costOf(unit, it->second) / double(std::max<std::size_t>(unit.tasks.size(), 1));
      ++known;
    }
  // Per task, the mean over the units the timings know (1 ms when none).
  const double meanPerTask = known > 0 ? knownSum / known : 1.0;
  for (const RunUnit& unit : units) {
    const auto it = timings->find(unit.test);
    costs.push_back(it != timings->end() ? costOf(unit, it->second) : meanPerTask * double(unit.tasks.size()));
  }
  return costs;
}

std::vector<int> assignShards(const std::vector<double>& costs, int total) {
  std::vector<std::size_t> order(costs.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return costs[a] > costs[b]; });
  std::vector<double> load(std::size_t(std::max(total, 1)), 0.0);
  std::vector<int> shardOf(costs.size(), 0);
  for (const std::size_t unit : order) {
    const auto lightest = std::min_element(load.begin(), load.end());  // the first of equals
    shardOf[unit] = int(lightest - load.begin());
    *lightest += costs[unit];
  }
  return shardOf;
}

std::string partitionDigest(const std::vector<RunUnit>& units, const std::vector<int>& shardOfUnit, int total) {
  std::string text = "lightcts-partition\n" + std::to_string(total) + "\n";
  for (std::size_t u = 0; u < units.size(); ++u)
    text += units[u].test + " " + std::to_string(units[u].tasks.size()) + " " + std::to_string(shardOfUnit[u]) + "\n";
  return baking::toHex(baking::sha256(text.data(), text.size()));
}

std::vector<WorkerPart> workerParts(const std::vector<RunUnit>& units, std::size_t combinations,
                                    std::size_t perPart) {
  std::vector<WorkerPart> parts;
  for (std::size_t c = 0; c < combinations; ++c) {
    std::vector<WorkerTask> model;
    using Shaders = std::pair<shaders::Mutant, shaders::Admissible>;
    std::vector<Shaders> variantOrder;
    std::map<Shaders, std::vector<WorkerTask>> byVariant;
    for (const RunUnit& unit : units) {
      if (unit.combination != c) continue;
      for (const WorkerTask& task : unit.tasks) {
        if (task.isModelTest()) {
          model.push_back(task);
          continue;
        }
        auto& list = byVariant[{task.mutant, task.admissible}];
        if (list.empty()) variantOrder.push_back({task.mutant, task.admissible});
        list.push_back(task);
      }
    }
    int number = 0;
    for (std::size_t start = 0; start < model.size(); start += perPart) {
      const std::size_t end = std::min(model.size(), start + perPart);
      parts.push_back({c, number++, {model.begin() + std::ptrdiff_t(start), model.begin() + std::ptrdiff_t(end)}});
    }
    // Whole mutants and admissible variants, packed in order into parts of
    // up to perPart tasks: checked against its killers a mutant
    // has a few tasks, and a worker per mutant would spend more on starting
    // its backend than on them. A variant's tasks, one per scene, fill parts
    // of their own.
    std::vector<WorkerTask> packed;
    for (const Shaders& variant : variantOrder) {
      std::vector<WorkerTask>& block = byVariant[variant];
      if (!packed.empty() && packed.size() + block.size() > perPart)
        parts.push_back({c, number++, std::exchange(packed, {})});
      packed.insert(packed.end(), block.begin(), block.end());
    }
    if (!packed.empty()) parts.push_back({c, number++, std::move(packed)});
  }
  return parts;
}

}  // namespace runner
