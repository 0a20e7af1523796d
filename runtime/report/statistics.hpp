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
//   scipy.stats.levene(a, b, center="median")), p from the F distribution;
// - Fisher's exact test of a 2x2 table (success rates: scipy.stats.fisher_exact);
// - evaluations to success with censoring (a run that never succeeded): Gehan's generalised
//   Wilcoxon test, which with one censoring point common to both samples is the Mann-Whitney
//   U test with every censored run tied above every observed value (below).
// A test that is undefined for its samples (too few values, no variance) gives NaN for its
// statistic and p-value, which every output prints as `n/a`.
#include <cstddef>
#include <optional>
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

// Fisher's exact test of the table [[successes_a, failures_a], [successes_b, failures_b]],
// two-sided as scipy.stats.fisher_exact: p is the sum of the hypergeometric probabilities
// (Boost.Math) of every table with the same margins that is at most as probable as the one
// observed. "At most" has a relative tolerance of 1e-7 (R's fisher.test; SciPy 1.10.1 has
// 1e-14, which tells apart no table of the sizes checked): tables equally probable in exact
// arithmetic, as the mirror images of a symmetric one, may differ in their last bits.
struct FisherResult {
  // The sample odds ratio (successes_a failures_b) / (failures_a successes_b): infinite when
  // the denominator is 0, NaN when a row or a column of the table is empty (then p is 1).
  double odds_ratio = 0.0;
  double p_value = 1.0;
};
[[nodiscard]] FisherResult fisher_exact(std::size_t successes_a, std::size_t failures_a, std::size_t successes_b,
                                        std::size_t failures_b);
inline constexpr double kFisherRelativeTolerance = 1e-7;

// Evaluations to success of two samples of runs, a run that never succeeded given as none:
// it is censored, known only to need more than the `budget` evaluations it was allowed. With
// one censoring point common to both samples, Gehan's generalised Wilcoxon test is the
// Mann-Whitney U test with every censored run tied above every observed one, so each counts
// as budget + 1 and mann_whitney_u (method auto) tests them: the ties of two or more censored
// runs make it asymptotic with the tie correction, as SciPy does. U is the first sample's:
// large when it needs more evaluations. `budget` is at least every observed value (a larger
// observed value raises it). Undefined as mann_whitney_u (every run censored, ...).
[[nodiscard]] TestResult censored_mann_whitney(std::span<const std::optional<double>> a,
                                               std::span<const std::optional<double>> b, double budget);

}  // namespace esc::report
