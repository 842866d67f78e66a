#include "runner/run_progress.h"

#include <cmath>
#include <sstream>

namespace runner {
namespace {

std::string duration(double seconds) {
  std::ostringstream text;
  if (seconds < 90) {
    text << int(std::lround(seconds)) << " s";
  } else {
    text << int(std::lround(seconds / 60)) << " min";
  }
  return text.str();
}

// VT100 codes every terminal emulator understands: up one line, erase it.
constexpr const char* kLineUp = "\x1b[1A";
constexpr const char* kEraseLine = "\r\x1b[2K";

}  // namespace

RunProgress::RunProgress(std::ostream& out, bool terminal, std::vector<std::string> names,
                         std::vector<std::size_t> totals)
    : out_(out), terminal_(terminal) {
  for (std::size_t c = 0; c < names.size(); ++c) {
    Combination combination;
    combination.name = std::move(names[c]);
    combination.total = c < totals.size() ? totals[c] : 0;
    combinations_.push_back(std::move(combination));
  }
}

RunProgress::~RunProgress() { finish(); }

std::string RunProgress::line(std::size_t index) const {
  const Combination& c = combinations_[index];
  std::ostringstream text;
  text << "run: " << c.name << ": " << c.done << "/" << c.total << " tests, " << c.failed << " failed";
  if (c.started) {
    const double elapsed = std::chrono::duration<double>(Clock::now() - c.start).count();
    text << ", " << duration(elapsed);
    if (c.done == c.total) {
      text << ", done";
    } else if (c.done > 0) {
      text << ", about " << duration(elapsed / double(c.done) * double(c.total - c.done)) << " left";
    }
  }
  return text.str();
}

void RunProgress::advance(std::size_t index, std::size_t count, bool failed) {
  std::lock_guard lock(mutex_);
  if (finished_ || index >= combinations_.size()) return;
  Combination& c = combinations_[index];
  if (!c.started) {
    c.started = true;
    c.start = Clock::now();
  }
  c.done += count;
  c.failed += failed ? count : 0;
  if (terminal_) {
    // A few redraws a second are all a reader sees; thousands would cost time.
    const auto now = Clock::now();
    if (c.done == c.total || now - lastDraw_ > std::chrono::milliseconds(200)) {
      lastDraw_ = now;
      redraw();
    }
    return;
  }
  const int tenths = c.total == 0 ? 10 : int(c.done * 10 / c.total);
  if (tenths > c.printedTenths && (tenths > 0 || c.done == c.total)) {
    c.printedTenths = tenths;
    out_ << line(index) << std::endl;
  }
}

void RunProgress::taskDone(std::size_t combination, bool failed) { advance(combination, 1, failed); }

void RunProgress::tasksSkipped(std::size_t combination, std::size_t count) {
  if (count > 0) advance(combination, count, false);
}

void RunProgress::note(const std::string& text) {
  std::lock_guard lock(mutex_);
  if (terminal_ && !finished_) erase();
  out_ << text << std::endl;
  if (terminal_ && !finished_) redraw();
}

void RunProgress::finish() {
  std::lock_guard lock(mutex_);
  finished_ = true;
}

void RunProgress::erase() {
  for (; drawnLines_ > 0; --drawnLines_) out_ << kLineUp << kEraseLine;
}

void RunProgress::redraw() {
  erase();
  for (std::size_t c = 0; c < combinations_.size(); ++c) out_ << kEraseLine << line(c) << "\n";
  drawnLines_ = combinations_.size();
  out_ << std::flush;
}

}  // namespace runner
