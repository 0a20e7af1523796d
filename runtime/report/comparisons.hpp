#pragma once
// Families of pairwise comparisons, as the end table, the report and summary.json show
// them: for each pair of samples the Welch and Mann-Whitney tests and the A12 effect size,
// the Brown-Forsythe test of equal spread (the paper's claims are about variance as well as
// level), and each test's p-values adjusted by Holm's step-down method over the family (the pairs
// shown together), which bounds the chance of any false discovery among them by alpha
// without the independence Bonferroni-Sidak needs and with more power than Bonferroni.
#include <cstddef>
#include <span>
#include <utility>
#include <vector>

#include "runtime/report/statistics.hpp"

namespace esc::report {

// Holm-adjusted p-values, in the order given. NaN (undefined tests) stays NaN and is not
// counted in the family's size.
[[nodiscard]] std::vector<double> holm(std::span<const double> p);

struct Comparison {
  std::size_t a = 0, b = 0;      // indices of the samples compared
  TestResult welch, mann_whitney;
  double a12 = 0.0;              // Vargha-Delaney A12 of a over b
  TestResult spread;             // Brown-Forsythe: equal spread (Levene's test about the medians)
  double sd_ratio = 0.0;         // sd of a / sd of b (NaN when undefined)
  double welch_p_holm = 0.0;     // adjusted over the family's Welch tests
  double mann_whitney_p_holm = 0.0;
  double spread_p_holm = 0.0;
};

// One comparison per pair (in the order given), adjusted as one family.
[[nodiscard]] std::vector<Comparison> compare(std::span<const std::vector<double>> samples,
                                              std::span<const std::pair<std::size_t, std::size_t>> pairs);

// Every pair i < j of `count` samples, in order.
[[nodiscard]] std::vector<std::pair<std::size_t, std::size_t>> all_pairs(std::size_t count);

}  // namespace esc::report
