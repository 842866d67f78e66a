// Runs a function for every row of an image on several threads. Rows are
// handed out one at a time, so uneven rows (a light-heavy band) balance out.
#pragma once

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace reference {

template <class RowFunction>
void forEachRow(int rows, int threads, RowFunction&& perRow) {
  if (threads <= 0) threads = int(std::max(1u, std::thread::hardware_concurrency()));
  threads = std::min(threads, std::max(rows, 1));
  std::atomic<int> next{0};
  auto worker = [&] {
    for (int row = next++; row < rows; row = next++) perRow(row);
  };
  std::vector<std::jthread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
}

}  // namespace reference
