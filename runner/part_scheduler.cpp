#include "runner/part_scheduler.h"

#include <algorithm>
#include <condition_variable>
#include <deque>
#include <exception>
#include <map>
#include <mutex>
#include <thread>

namespace runner {
namespace {

class PartQueue {
 public:
  PartQueue(const std::vector<WorkerPart>& parts, bool gated) {
    for (std::size_t p = 0; p < parts.size(); ++p) {
      const std::size_t c = parts[p].combination;
      if (!gated || !firstOf_.count(c)) {
        firstOf_.emplace(c, p);
        ready_.push_back(p);
      } else {
        held_[c].push_back(p);
      }
      combinationOf_.push_back(c);
    }
  }

  // The next part to run; false when none is ready and none is held (a held
  // part waits on its combination's first part, which some thread runs).
  bool take(std::size_t& part) {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return !ready_.empty() || held_.empty(); });
    if (ready_.empty()) return false;
    part = ready_.front();
    ready_.pop_front();
    return true;
  }

  // The combination of `part` has its backend: its held parts may run.
  void release(std::size_t part) {
    std::lock_guard lock(mutex_);
    auto it = held_.find(combinationOf_[part]);
    if (it == held_.end()) return;
    ready_.insert(ready_.end(), it->second.begin(), it->second.end());
    held_.erase(it);
    changed_.notify_all();
  }

  // `part` is done; returns the parts of its combination still held (to skip)
  // when it was the combination's first and never released them.
  std::vector<std::size_t> finish(std::size_t part) {
    std::lock_guard lock(mutex_);
    std::vector<std::size_t> skipped;
    auto it = held_.find(combinationOf_[part]);
    if (it != held_.end()) {
      skipped = std::move(it->second);
      held_.erase(it);
    }
    changed_.notify_all();
    return skipped;
  }

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::size_t> ready_;
  std::map<std::size_t, std::vector<std::size_t>> held_;  // by combination
  std::map<std::size_t, std::size_t> firstOf_;
  std::vector<std::size_t> combinationOf_;
};

}  // namespace

void runPartsInParallel(const std::vector<WorkerPart>& parts, int jobs,
                        const std::function<void(std::size_t, const std::function<void()>&)>& run,
                        const std::function<void(std::size_t, std::size_t)>& skip) {
  PartQueue queue(parts, bool(skip));
  std::mutex errorMutex;
  std::exception_ptr error;
  auto keepFirstError = [&] {
    std::lock_guard lock(errorMutex);
    if (!error) error = std::current_exception();
  };
  auto work = [&] {
    std::size_t part = 0;
    while (queue.take(part)) {
      try {
        run(part, [&queue, part] { queue.release(part); });
      } catch (...) {
        keepFirstError();
      }
      for (const std::size_t skipped : queue.finish(part)) try {
          if (skip) skip(skipped, part);
        } catch (...) {
          keepFirstError();
        }
    }
  };
  const std::size_t threads = std::min<std::size_t>(std::size_t(std::max(jobs, 1)), std::max<std::size_t>(parts.size(), 1));
  std::vector<std::jthread> pool;
  for (std::size_t t = 0; t < threads; ++t) pool.emplace_back(work);
  pool.clear();  // joins
  if (error) std::rethrow_exception(error);
}

}  // namespace runner
