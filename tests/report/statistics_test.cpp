#include "runtime/report/statistics.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

namespace esc::report {
namespace {

TEST(Statistics, MatchesHandComputedValues) {
  const std::vector<double> x = {2, 4, 4, 4, 5, 5, 7, 9};
  const Summary s = summarise(x);
  EXPECT_EQ(s.n, 8U);
  EXPECT_DOUBLE_EQ(s.mean, 5.0);
  EXPECT_NEAR(s.sd, 2.138089935299395, 1e-12);   // sqrt(32 / 7)
  EXPECT_DOUBLE_EQ(s.median, 4.5);
  EXPECT_DOUBLE_EQ(s.min, 2.0);
  EXPECT_DOUBLE_EQ(s.max, 9.0);
}

TEST(Statistics, SmallSamples) {
  EXPECT_EQ(summarise(std::vector<double>{}).n, 0U);
  const Summary one = summarise(std::vector<double>{3.5});
  EXPECT_DOUBLE_EQ(one.mean, 3.5);
  EXPECT_DOUBLE_EQ(one.sd, 0.0);
  EXPECT_DOUBLE_EQ(one.median, 3.5);
}

}  // namespace
}  // namespace esc::report

namespace esc::report {
namespace {

// Reference values computed independently with SciPy 1.10.1 (Debian python3-scipy):
//   stats.ttest_ind(a, b, equal_var=False)
//   stats.mannwhitneyu(a, b, alternative="two-sided", method="asymptotic", use_continuity=True)
struct Reference {
  std::vector<double> a, b;
  double t, t_p, df, u, u_p;
};

const std::vector<Reference>& references() {
  static const std::vector<Reference> r = {
      {{19.1, 21.4, 18.7, 22.3, 20.5, 19.9, 23.1, 18.2, 20.8, 21.7},
       {17.2, 18.9, 16.5, 19.4, 17.8, 18.1, 20.2, 16.9, 17.5, 18.6},
       3.9229798778206626, 0.0011587360429312936, 16.442519867750786, 90.0, 0.0028272720911168077},
      {{1, 2, 2, 3, 3, 3, 4, 5}, {2, 3, 3, 4, 4, 5, 5, 6, 7},   // many ties
       -2.122744235620042, 0.05104508769182007, 14.818510553350144, 17.0, 0.06935045438181722},
      {{10.5, 12.25, 9.75, 11.0, 13.5}, {8.0, 15.0, 6.5, 17.25, 9.0, 14.0, 7.5},   // unequal sizes and spreads
       0.20860073431196707, 0.8400613553841353, 7.864100811498811, 20.0, 0.7453330673308027},
  };
  return r;
}

TEST(Statistics, WelchMatchesScipy) {
  for (const Reference& r : references()) {
    const TestResult w = welch_t_test(r.a, r.b);
    EXPECT_NEAR(w.statistic, r.t, 1e-12);
    EXPECT_NEAR(w.df, r.df, 1e-10);
    EXPECT_NEAR(w.p_value, r.t_p, 1e-12 + 1e-9 * r.t_p);
  }
}

TEST(Statistics, MannWhitneyMatchesScipy) {
  for (const Reference& r : references()) {
    const TestResult m = mann_whitney_u(r.a, r.b);
    EXPECT_DOUBLE_EQ(m.statistic, r.u);
    EXPECT_NEAR(m.p_value, r.u_p, 1e-12 + 1e-9 * r.u_p);
    // Swapping the samples keeps the p-value and gives the other U.
    const TestResult swapped = mann_whitney_u(r.b, r.a);
    EXPECT_NEAR(swapped.p_value, m.p_value, 1e-15);
    EXPECT_DOUBLE_EQ(swapped.statistic, static_cast<double>(r.a.size() * r.b.size()) - r.u);
  }
}

TEST(Statistics, UndefinedTestsGiveNaN) {
  const std::vector<double> one = {1.0};
  const std::vector<double> flat = {2.0, 2.0, 2.0};
  EXPECT_TRUE(std::isnan(welch_t_test(one, flat).p_value));
  EXPECT_TRUE(std::isnan(welch_t_test(flat, flat).p_value));
  EXPECT_TRUE(std::isnan(mann_whitney_u(flat, flat).p_value));
  EXPECT_TRUE(std::isnan(mann_whitney_u({}, flat).p_value));
  // Identical samples with spread: no difference at all.
  const std::vector<double> x = {1, 2, 3, 4};
  EXPECT_NEAR(welch_t_test(x, x).p_value, 1.0, 1e-12);
  EXPECT_NEAR(mann_whitney_u(x, x).p_value, 1.0, 1e-12);
}

}  // namespace
}  // namespace esc::report
