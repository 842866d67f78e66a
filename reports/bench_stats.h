// The two-sided Mann-Whitney U test (Wilcoxon rank-sum) for comparing the
// per-repetition times of one benchmark before and after a change: no
// assumption of normal times, robust to one slow outlier.
#pragma once

#include <cstdint>
#include <vector>

namespace reports {

struct MannWhitney {
  double u1 = 0;     // U of the first sample: its rank sum less n1(n1+1)/2 (midranks for ties)
  double u = 0;      // min(U1, U2), the usual reported U
  double p = 1;      // two-sided p-value
  bool exact = false;  // p by enumeration of every assignment of the pooled ranks
  bool ties = false;
};

// Exact p when C(n1+n2, n1) <= maxExactArrangements: every way of choosing
// n1 of the pooled (mid)ranks is enumerated and p is the fraction whose
// |U - n1 n2 / 2| is at least the observed one (with ties this is the exact
// permutation distribution given the ties). Otherwise the normal
// approximation with tie correction and a continuity correction of 0.5:
//   sigma^2 = n1 n2 / 12 * ((n + 1) - sum(t^3 - t) / (n (n - 1))),
//   z = (|U1 - n1 n2 / 2| - 0.5) / sigma, p = erfc(z / sqrt 2).
// Empty samples, or all values equal, give p = 1.
MannWhitney mannWhitneyU(const std::vector<double>& a, const std::vector<double>& b,
                         std::uint64_t maxExactArrangements = 200000);

}  // namespace reports
