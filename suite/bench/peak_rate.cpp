// The peak-rate kernel: independent chains of `acc = acc * a + b` in single
// precision, as wide as the CPU's vector unit, on every hardware thread.
//
// The binary must run on any x86-64 machine, so nothing here is compiled for
// the build machine (-march=native): the widest kernel is chosen at run time
// with __builtin_cpu_supports, and each one is compiled for its own
// instruction set with GCC's target attribute:
//   avx512f: 16-wide FMA (vfmadd on zmm), 2 flops per lane
//   avx2+fma: 8-wide FMA (vfmadd on ymm), 2 flops per lane
//   sse2 (every x86-64): 4-wide multiply then add (no FMA in SSE2), 2 flops per lane
// Each thread runs kChains independent accumulators so the FMA latency is
// hidden (latency 4 x 2 ports = 8 in flight; 12 is enough on current cores).
// It measures the arithmetic peak only: no memory traffic, no transcendental
// unit, every value in registers.
#include "suite/bench/peak_rate.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <thread>
#include <vector>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define LIGHTCTS_PEAK_X86 1
#endif

namespace bench {
namespace {

constexpr int kChains = 12;
// acc -> a * acc + b converges to b / (1 - a) = 1: the values stay near 1
// (no overflow, no subnormals), whatever the iteration count.
constexpr float kA = 0.999999f;
constexpr float kB = 1.0f - kA;

struct Kernel {
  const char* name;
  int lanes;                      // floats per vector
  double (*run)(std::int64_t);    // returns the sum of the accumulators
};

#ifdef LIGHTCTS_PEAK_X86
__attribute__((target("avx512f"))) double runAvx512(std::int64_t iterations) {
  __m512 acc[kChains];
  for (int j = 0; j < kChains; ++j) acc[j] = _mm512_set1_ps(1.0f + 0.01f * float(j));
  const __m512 a = _mm512_set1_ps(kA), b = _mm512_set1_ps(kB);
  for (std::int64_t i = 0; i < iterations; ++i) {
#pragma GCC unroll 12
    for (int j = 0; j < kChains; ++j) acc[j] = _mm512_fmadd_ps(acc[j], a, b);
  }
  double sum = 0;
  for (int j = 0; j < kChains; ++j) {
    alignas(64) float lanes[16];
    _mm512_store_ps(lanes, acc[j]);
    for (float v : lanes) sum += double(v);
  }
  return sum;
}

__attribute__((target("avx2,fma"))) double runAvx2(std::int64_t iterations) {
  __m256 acc[kChains];
  for (int j = 0; j < kChains; ++j) acc[j] = _mm256_set1_ps(1.0f + 0.01f * float(j));
  const __m256 a = _mm256_set1_ps(kA), b = _mm256_set1_ps(kB);
  for (std::int64_t i = 0; i < iterations; ++i) {
#pragma GCC unroll 12
    for (int j = 0; j < kChains; ++j) acc[j] = _mm256_fmadd_ps(acc[j], a, b);
  }
  double sum = 0;
  for (int j = 0; j < kChains; ++j) {
    alignas(32) float lanes[8];
    _mm256_store_ps(lanes, acc[j]);
    for (float v : lanes) sum += double(v);
  }
  return sum;
}

double runSse2(std::int64_t iterations) {
  __m128 acc[kChains];
  for (int j = 0; j < kChains; ++j) acc[j] = _mm_set1_ps(1.0f + 0.01f * float(j));
  const __m128 a = _mm_set1_ps(kA), b = _mm_set1_ps(kB);
  for (std::int64_t i = 0; i < iterations; ++i) {
#pragma GCC unroll 12
    for (int j = 0; j < kChains; ++j) acc[j] = _mm_add_ps(_mm_mul_ps(acc[j], a), b);
  }
  double sum = 0;
  for (int j = 0; j < kChains; ++j) {
    alignas(16) float lanes[4];
    _mm_store_ps(lanes, acc[j]);
    for (float v : lanes) sum += double(v);
  }
  return sum;
}
#endif

#ifndef LIGHTCTS_PEAK_X86
// Anything else: scalar multiply-add chains (the compiler may vectorise them).
double runScalar(std::int64_t iterations) {
  std::array<float, kChains * 4> acc;
  for (std::size_t j = 0; j < acc.size(); ++j) acc[j] = 1.0f + 0.01f * float(j);
  for (std::int64_t i = 0; i < iterations; ++i)
    for (float& v : acc) v = v * kA + kB;
  double sum = 0;
  for (float v : acc) sum += double(v);
  return sum;
}
#endif

Kernel chooseKernel() {
#ifdef LIGHTCTS_PEAK_X86
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx512f"))
    return {"avx512f: 12 independent 16-wide single-precision FMA chains per thread", 16, runAvx512};
  if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"))
    return {"avx2+fma: 12 independent 8-wide single-precision FMA chains per thread", 8, runAvx2};
  return {"sse2: 12 independent 4-wide single-precision multiply-add chains per thread", 4, runSse2};
#else
  return {"scalar: 48 independent single-precision multiply-add chains per thread", 4, runScalar};
#endif
}

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// One timed run on `threads` threads, all released together; returns the
// wall-clock seconds from the release to the last thread's end.
double timedRun(const Kernel& kernel, std::int64_t iterations, int threads, double& checksum) {
  std::atomic<int> ready{0};
  std::atomic<bool> go{false};
  std::vector<double> sums(std::size_t(threads), 0.0);
  std::vector<std::thread> pool;
  pool.reserve(std::size_t(threads));
  for (int t = 0; t < threads; ++t) {
    pool.emplace_back([&, t] {
      ready.fetch_add(1);
      while (!go.load(std::memory_order_acquire)) std::this_thread::yield();
      sums[std::size_t(t)] = kernel.run(iterations);
    });
  }
  while (ready.load() < threads) std::this_thread::yield();
  const Clock::time_point start = Clock::now();
  go.store(true, std::memory_order_release);
  for (std::thread& th : pool) th.join();
  const double seconds = secondsSince(start);
  checksum = 0;
  for (double s : sums) checksum += s;
  return seconds;
}

}  // namespace

PeakRate measurePeakRate(int repetitions, double secondsPerRun) {
  const Kernel kernel = chooseKernel();
  PeakRate rate;
  rate.kernel = kernel.name;
  rate.threads = int(std::max(1u, std::thread::hardware_concurrency()));
  rate.repetitions = std::max(1, repetitions);

  // Calibration on one thread: double the count until a run lasts 1/8 of the
  // target, then scale to the target.
  std::int64_t iterations = 1 << 12;
  double checksum = 0;
  for (;;) {
    const double seconds = timedRun(kernel, iterations, 1, checksum);
    if (seconds >= secondsPerRun / 8 || iterations > (std::int64_t(1) << 40)) {
      iterations = std::max<std::int64_t>(1, std::int64_t(double(iterations) * secondsPerRun / std::max(seconds, 1e-9)));
      break;
    }
    iterations *= 2;
  }

  const double flopsPerRun = double(iterations) * kChains * kernel.lanes * 2.0 * rate.threads;
  std::vector<double> gflops;
  for (int r = 0; r < rate.repetitions; ++r) {
    const double seconds = timedRun(kernel, iterations, rate.threads, checksum);
    gflops.push_back(flopsPerRun / seconds * 1e-9);
  }
  std::sort(gflops.begin(), gflops.end());
  const std::size_t n = gflops.size();
  rate.gflops = n % 2 == 1 ? gflops[n / 2] : 0.5 * (gflops[n / 2 - 1] + gflops[n / 2]);
  rate.checksum = checksum;
  return rate;
}

}  // namespace bench
