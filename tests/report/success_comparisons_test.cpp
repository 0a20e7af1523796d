// Success compared pair by pair (success_comparisons.hpp): each run's evaluations to success
// and its budget, one censoring point per pair (the larger budget + 1), Fisher's and the
// censored Mann-Whitney test each adjusted over the family.
#include <cmath>
#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "runtime/report/comparisons.hpp"
#include "runtime/report/success_comparisons.hpp"

namespace esc::report {
namespace {

eval::RunResult run(std::optional<std::int64_t> success, std::int64_t evaluations) {
  eval::RunResult r;
  r.success_evaluation = success;
  eval::GenerationStats g;
  g.evaluations = evaluations;
  r.generations = {g, g};
  return r;
}

std::vector<std::pair<std::size_t, std::size_t>> one_pair() { return {{0, 1}}; }

TEST(SuccessComparisons, CensorAtThePairsLargestBudgetAndAdjustEachTest) {
  // Budgets: 2 x 100 evaluations per run in the first sample, 2 x 150 in the others.
  const std::vector<eval::RunResult> a{run(10, 100), run(std::nullopt, 100), run(50, 100)};
  const std::vector<eval::RunResult> b{run(std::nullopt, 150), run(std::nullopt, 150), run(280, 150)};
  const std::vector<eval::RunResult> c{run(1, 150), run(2, 150), run(3, 150)};
  const std::vector<SuccessSample> samples{success_sample(a), success_sample(b), success_sample(c)};
  EXPECT_EQ(samples[0].budget, 200.0);
  EXPECT_EQ(samples[1].budget, 300.0);
  const std::vector<std::pair<std::size_t, std::size_t>> pairs{{0, 1}, {0, 2}, {1, 2}};
  const std::vector<SuccessComparison> cs = compare_success(samples, pairs);
  ASSERT_EQ(cs.size(), 3u);
  EXPECT_EQ(cs[0].censored_at, 301.0);
  EXPECT_EQ(cs[0].successes_a, 2u);
  EXPECT_EQ(cs[0].runs_b, 3u);
  for (const SuccessComparison& k : cs) {
    const SuccessSample& x = samples[k.a];
    const SuccessSample& y = samples[k.b];
    EXPECT_EQ(k.censored.p_value, censored_mann_whitney(x.evaluations, y.evaluations, k.censored_at - 1).p_value);
    EXPECT_EQ(k.fisher.p_value, fisher_exact(k.successes_a, k.runs_a - k.successes_a, k.successes_b,
                                             k.runs_b - k.successes_b).p_value);
  }
  std::vector<double> fisher_p, censored_p;
  for (const SuccessComparison& k : cs) {
    fisher_p.push_back(k.fisher.p_value);
    censored_p.push_back(k.censored.p_value);
  }
  const std::vector<double> fh = holm(fisher_p), ch = holm(censored_p);
  for (std::size_t k = 0; k < cs.size(); ++k) {
    EXPECT_EQ(cs[k].fisher_p_holm, fh[k]);
    EXPECT_EQ(cs[k].censored_p_holm, ch[k]);
  }
  // Every run of a pair succeeded: nothing is censored, and no budget is shown.
  const std::vector<SuccessSample> solved{samples[2], samples[2]};
  const SuccessComparison all = compare_success(solved, one_pair()).front();
  EXPECT_TRUE(std::isnan(all.censored_at));
  EXPECT_EQ(all.censored.p_value, censored_mann_whitney(solved[0].evaluations, solved[1].evaluations, 300).p_value);
  // A sample without a finished run compares to nothing.
  const std::vector<SuccessSample> with_empty{samples[0], SuccessSample{}};
  const std::vector<std::pair<std::size_t, std::size_t>> one{{0, 1}};
  EXPECT_TRUE(std::isnan(compare_success(with_empty, one).front().fisher.p_value));
}

}  // namespace
}  // namespace esc::report
