#pragma once
// Descriptive statistics of a sample (final best fitness over runs, ...) and the tests used
// to compare two samples, all two-sided, each matching SciPy 1.10 (values checked in
// tests/report/statistics_test.cpp):
// - Welch's t-test (unequal variances, Welch-Satterthwaite degrees of freedom), p from
//   Student's t distribution (Boost.Math): scipy.stats.ttest_ind(a, b, equal_var=False);
// - the Mann-Whitney U test as scipy.stats.mannwhitneyu(a, b, method="auto"): the exact
//   distribution of U when one sample has at most 8 values and there are no ties (what
//   campaigns of a few runs give), else the normal approximation with average ranks for
//   ties, the tie-corrected variance and a continuity correction of 0.5;
// - the Vargha-Delaney A12 effect size, P(a > b) + P(a = b) / 2;
// - the Brown-Forsythe test of equal variances (Levene's test centred on the medians:
//   scipy.stats.levene(a, b, center="median")), p from the F distribution.
// A test that is undefined for its samples (too few values, no variance) gives NaN for its
// statistic and p-value, which every output prints as `n/a`.
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
  double statistic = 0.0;   // Welch: t (a minus b); Mann-Whitney: U of the first sample;
                            // Brown-Forsythe: W (an F statistic)
  double df = 0.0;          // Welch: degrees of freedom; Brown-Forsythe: the denominator's
                            // (the numerator's is 1 for two samples); Mann-Whitney: 0
  double p_value = 1.0;     // two-sided; NaN when the test is undefined
  bool exact = false;       // Mann-Whitney: p from the exact distribution of U
};

// Undefined when either sample has fewer than 2 values, or both have zero variance.
[[nodiscard]] TestResult welch_t_test(std::span<const double> a, std::span<const double> b);

enum class UMethod { Auto, Exact, Asymptotic };
// Undefined when either sample is empty, or (asymptotic) all values are equal. Exact is
// refused (asymptotic used) for ties, as SciPy's "auto" does, and when the smaller sample
// times the whole U range exceeds kMaxExactCells (the exact count would take minutes).
inline constexpr double kMaxExactCells = 2e8;
[[nodiscard]] TestResult mann_whitney_u(std::span<const double> a, std::span<const double> b,
                                        UMethod method = UMethod::Auto);

// NaN when either sample is empty; 0.5 means no effect, 1 that every a beats every b.
[[nodiscard]] double vargha_delaney_a12(std::span<const double> a, std::span<const double> b);

// Undefined when either sample has fewer than 2 values, or the absolute deviations from the
// medians are equal within each sample (none differs from its median; two values per sample).
[[nodiscard]] TestResult brown_forsythe(std::span<const double> a, std::span<const double> b);

}  // namespace esc::report
