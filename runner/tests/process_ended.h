// For the runner's tests that kill processes: whether a process is gone.
#pragma once

#include <chrono>
#include <fstream>
#include <string>
#include <thread>

namespace runner::testing {

// True when `pid` is gone or a zombie (killed, not yet reaped by init).
inline bool endedOrZombie(int pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string text;
  if (!std::getline(stat, text)) return true;
  const std::size_t close = text.rfind(')');
  return close == std::string::npos || text.size() < close + 3 || text[close + 2] == 'Z' || text[close + 2] == 'X';
}

// Waits up to 5 s for a killed process to be gone (the kernel ends it
// asynchronously); true when it is.
inline bool endsSoon(int pid) {
  for (int i = 0; i < 50; ++i) {
    if (endedOrZombie(pid)) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  return false;
}

}  // namespace runner::testing
