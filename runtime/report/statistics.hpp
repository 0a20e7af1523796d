#pragma once
// Descriptive statistics of a sample (final best fitness over runs, ...) and the two
// tests used to compare controllers, both two-sided:
// - Welch's t-test (unequal variances, Welch-Satterthwaite degrees of freedom), p from
//   Student's t distribution (Boost.Math);
// - the Mann-Whitney U test with the normal approximation, average ranks for ties, the
//   tie-corrected variance and a continuity correction of 0.5, p from the normal
//   distribution (Boost.Math). This is scipy.stats.mannwhitneyu(method="asymptotic",
//   use_continuity=True); with the 10 runs of a campaign an exact test would be possible
//   but the approximation is what the literature of the field reports.
#include <cstddef>
#include <span>

namespace esc::report {

struct Summary {
  std::size_t n = 0;
  double mean = 0.0;
  double sd = 0.0;       // sample standard deviation (n - 1); 0 for n < 2
  double median = 0.0;
  double min = 0.0;
  double max = 0.0;
};

[[nodiscard]] Summary summarise(std::span<const double> sample);

struct TestResult {
  double statistic = 0.0;   // Welch: t (a minus b); Mann-Whitney: U of the first sample
  double df = 0.0;          // Welch: degrees of freedom; Mann-Whitney: 0
  double p_value = 1.0;     // two-sided; NaN when the test is undefined
};

// NaN p-value when either sample has fewer than 2 values, or both have zero variance.
[[nodiscard]] TestResult welch_t_test(std::span<const double> a, std::span<const double> b);
// NaN p-value when either sample is empty or all values are equal (zero variance of U).
[[nodiscard]] TestResult mann_whitney_u(std::span<const double> a, std::span<const double> b);

}  // namespace esc::report
