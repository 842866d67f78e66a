#include "reports/bench_stats.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace reports {
namespace {

// C(n, k), saturating at `cap` + 1 so that large cases do not overflow.
std::uint64_t choose(std::uint64_t n, std::uint64_t k, std::uint64_t cap) {
  if (k > n) return 0;
  k = std::min(k, n - k);
  long double c = 1;
  for (std::uint64_t i = 1; i <= k; ++i) {
    c = c * (long double)(n - k + i) / (long double)i;
    if (c > (long double)cap) return cap + 1;
  }
  return std::uint64_t(std::llround(c));
}

// Counts the n1-subsets of `ranks` (twice the midranks, so integers) whose
// sum s satisfies |s - centre| >= distance (all in doubled units).
void enumerate(const std::vector<long long>& ranks, std::size_t from, int left, long long sum, long long centre2,
               long long distance2, std::uint64_t& extreme) {
  if (left == 0) {
    // 2 * (2 * sum) vs centre2 (which is 2 * 2 * expected sum)
    if (std::llabs(2 * sum - centre2) >= distance2) ++extreme;
    return;
  }
  for (std::size_t i = from; i + std::size_t(left) <= ranks.size(); ++i)
    enumerate(ranks, i + 1, left - 1, sum + ranks[i], centre2, distance2, extreme);
}

}  // namespace

MannWhitney mannWhitneyU(const std::vector<double>& a, const std::vector<double>& b,
                         std::uint64_t maxExactArrangements) {
  MannWhitney result;
  const std::size_t n1 = a.size(), n2 = b.size(), n = n1 + n2;
  if (n1 == 0 || n2 == 0) return result;

  // Pooled values with their sample, sorted; midranks doubled (integers).
  std::vector<std::pair<double, int>> pooled;
  for (double v : a) pooled.emplace_back(v, 0);
  for (double v : b) pooled.emplace_back(v, 1);
  std::sort(pooled.begin(), pooled.end(),
            [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<long long> rank2(n);  // 2 * midrank
  double tieTerm = 0;               // sum over tie groups of t^3 - t
  for (std::size_t i = 0; i < n;) {
    std::size_t j = i;
    while (j + 1 < n && pooled[j + 1].first == pooled[i].first) ++j;
    const long long t = (long long)(j - i + 1);
    for (std::size_t k = i; k <= j; ++k) rank2[k] = (long long)(i + 1) + (long long)(j + 1);  // 2 * mean rank
    if (t > 1) result.ties = true, tieTerm += double(t * t * t - t);
    i = j + 1;
  }
  long long rankSum2 = 0;  // 2 * R1
  for (std::size_t k = 0; k < n; ++k)
    if (pooled[k].second == 0) rankSum2 += rank2[k];
  const double r1 = double(rankSum2) / 2;
  result.u1 = r1 - double(n1) * double(n1 + 1) / 2;
  const double u2 = double(n1) * double(n2) - result.u1;
  result.u = std::min(result.u1, u2);
  const double mean = double(n1) * double(n2) / 2;

  if (tieTerm == double(n) * double(n) * double(n) - double(n)) {  // every value equal
    result.p = 1;
    result.exact = true;
    return result;
  }

  const std::uint64_t arrangements = choose(n, n1, maxExactArrangements);
  if (arrangements <= maxExactArrangements) {
    // In doubled rank units: expected 2*R1 is n1 (n + 1); compare 2*(2*R) with 2*n1(n+1).
    const long long centre2 = (long long)(2 * n1 * (n + 1));
    const long long distance2 = std::llabs(2 * rankSum2 - centre2);
    std::uint64_t extreme = 0;
    enumerate(rank2, 0, int(n1), 0, centre2, distance2, extreme);
    result.p = std::min(1.0, double(extreme) / double(arrangements));
    result.exact = true;
    return result;
  }

  const double nn = double(n);
  const double variance = double(n1) * double(n2) / 12 * ((nn + 1) - tieTerm / (nn * (nn - 1)));
  if (variance <= 0) return result;
  const double z = std::max(0.0, std::abs(result.u1 - mean) - 0.5) / std::sqrt(variance);
  result.p = std::min(1.0, std::erfc(z / std::sqrt(2.0)));
  return result;
}

}  // namespace reports
