#include "runtime/report/statistics.hpp"
#include "runtime/report/comparisons.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <optional>
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

// Reference values computed outside esc with SciPy 1.10.1 (Debian python3-scipy) and, for
// Holm, statsmodels 0.13.5 (python3-statsmodels):
//   stats.ttest_ind(a, b, equal_var=False)                      t, p (df by its formula)
//   stats.mannwhitneyu(a, b, alternative="two-sided", method="auto")         U, p
//   stats.mannwhitneyu(a, b, alternative="two-sided", method="asymptotic")   p
//   U / (len(a) * len(b))                                       A12
//   stats.levene(a, b, center="median")                         W, p (Brown-Forsythe)
struct Reference {
  std::vector<double> a, b;
  double t, t_p, df, u, u_p, u_p_asymptotic, a12, w, w_p;
  bool exact;   // method="auto" chose the exact distribution (a sample of <= 8, no ties)
};

const std::vector<Reference>& references() {
  static const std::vector<Reference> r = {
      {{19.1, 21.4, 18.7, 22.3, 20.5, 19.9, 23.1, 18.2, 20.8, 21.7},
       {17.2, 18.9, 16.5, 19.4, 17.8, 18.1, 20.2, 16.9, 17.5, 18.6},
       3.9229798778206626, 0.0011587360429312936, 16.442519867750786, 90.0, 0.0028272720911168077,
       0.0028272720911168077, 0.9, 1.1193857965451082, 0.30404353456881394, false},
      {{1, 2, 2, 3, 3, 3, 4, 5}, {2, 3, 3, 4, 4, 5, 5, 6, 7},   // many ties: asymptotic
       -2.122744235620042, 0.05104508769182007, 14.818510553350144, 17.0, 0.06935045438181722,
       0.06935045438181722, 0.2361111111111111, 0.6161682550115022, 0.44469637871570644, false},
      {{10.5, 12.25, 9.75, 11.0, 13.5}, {8.0, 15.0, 6.5, 17.25, 9.0, 14.0, 7.5},   // unequal sizes and spreads
       0.20860073431196707, 0.8400613553841353, 7.864100811498811, 20.0, 0.7550505050505051,
       0.7453330673308027, 0.5714285714285714, 2.8047687802080774, 0.12492414090213945, true},
      {{1088.4, 1092.1, 1079.5, 1101.2}, {889.7, 901.3, 870.2, 912.8},   // complete separation: p = 2 / C(8, 4)
       19.415171155815347, 2.0248270623902397e-05, 4.384673228962692, 16.0, 0.02857142857142857,
       0.03038282197657749, 1.0, 1.7609194100829235, 0.23277273115841304, true},
      {{3.1, 2.7, 4.4}, {1.2, 5.9, 3.3, 0.8}, 0.4697161901456929, 0.6627833855852261, 4.041286769821515, 7.0,
       0.8571428571428571, 0.8596837951986662, 0.5833333333333334, 2.3463878652840853, 0.18614087795603876, true},
      {{1306.4, 1311.2, 1299.8, 1308.5, 1302.1, 1315.7, 1304.9, 1309.3},
       {1267.5, 1281.4, 1259.9, 1288.2, 1301.0, 1273.6, 1262.3, 1279.8},
       5.860355835347375, 0.00025572770057047254, 8.85983383652938, 63.0, 0.0003108003108003108,
       0.0013593755271592322, 0.984375, 6.0464840759348295, 0.02756436666363478, true},
      {{0.5, 0.9, 0.1, 0.7, 0.3}, {0.2, 0.8, 0.6, 0.4, 0.05, 0.95, 0.55, 0.45, 0.35, 0.15, 0.25, 0.65},
       0.30927685641354324, 0.7666376445425749, 6.604994324631102, 33.0, 0.7989657401422106,
       0.7921473917958973, 0.55, 0.07871696698706782, 0.7828763760162034, true},
  };
  return r;
}

double tolerance(double v) { return 1e-12 + 1e-9 * std::fabs(v); }

TEST(Statistics, WelchMatchesScipy) {
  for (const Reference& r : references()) {
    const TestResult w = welch_t_test(r.a, r.b);
    EXPECT_NEAR(w.statistic, r.t, 1e-12);
    EXPECT_NEAR(w.df, r.df, 1e-10);
    EXPECT_NEAR(w.p_value, r.t_p, tolerance(r.t_p));
  }
}

TEST(Statistics, MannWhitneyMatchesScipyAuto) {
  for (const Reference& r : references()) {
    const TestResult m = mann_whitney_u(r.a, r.b);
    EXPECT_DOUBLE_EQ(m.statistic, r.u);
    EXPECT_EQ(m.exact, r.exact);
    EXPECT_NEAR(m.p_value, r.u_p, tolerance(r.u_p));
    // Swapping the samples keeps the p-value and gives the other U.
    const TestResult swapped = mann_whitney_u(r.b, r.a);
    EXPECT_NEAR(swapped.p_value, m.p_value, 1e-15);
    EXPECT_DOUBLE_EQ(swapped.statistic, static_cast<double>(r.a.size() * r.b.size()) - r.u);
  }
}

TEST(Statistics, ExactMannWhitneyWithOneSmallSample) {
  // 8 against 40 values: SciPy's "auto" is exact whenever one sample has at most 8.
  const std::vector<double> a = {0.371, 1.482, 3.333, 5.924, 9.255, 13.326, 0.837, 6.388};
  const std::vector<double> b = {3.5307,  5.1214,  7.7721,  11.4828, 16.2535, 22.0842, 9.8749,  17.8256, 7.7363,
                                 17.807,  9.8377,  22.0284, 16.1791, 11.3898, 7.6605,  4.9912,  3.3819,  21.9326,
                                 3.3433,  4.914,   7.5447,  11.2354, 15.9861, 21.7968, 9.5675,  17.4982, 7.3889,
                                 17.4396, 9.4503,  21.621,  15.7517, 10.9424, 7.1931,  4.5038,  21.9745, 21.4052,
                                 21.8959, 4.3466,  6.9573,  10.628};
  const TestResult m = mann_whitney_u(a, b);
  EXPECT_TRUE(m.exact);
  EXPECT_DOUBLE_EQ(m.statistic, 55.0);
  EXPECT_NEAR(m.p_value, 0.0025286936368511957, tolerance(0.0025286936368511957));
}

TEST(Statistics, MannWhitneyAsymptoticMatchesScipy) {
  for (const Reference& r : references())
    EXPECT_NEAR(mann_whitney_u(r.a, r.b, UMethod::Asymptotic).p_value, r.u_p_asymptotic,
                tolerance(r.u_p_asymptotic));
}

TEST(Statistics, ExactMannWhitneyIsRefusedForTies) {
  const Reference& tied = references()[1];
  const TestResult m = mann_whitney_u(tied.a, tied.b, UMethod::Exact);
  EXPECT_FALSE(m.exact);
  EXPECT_NEAR(m.p_value, tied.u_p_asymptotic, tolerance(tied.u_p_asymptotic));
}

TEST(Statistics, VarghaDelaneyA12) {
  for (const Reference& r : references()) {
    EXPECT_NEAR(vargha_delaney_a12(r.a, r.b), r.a12, 1e-15);
    EXPECT_NEAR(vargha_delaney_a12(r.b, r.a), 1.0 - r.a12, 1e-15);
  }
  const std::vector<double> flat = {2.0, 2.0};
  EXPECT_DOUBLE_EQ(vargha_delaney_a12(flat, flat), 0.5);
}

TEST(Statistics, BrownForsytheMatchesScipyLevene) {
  for (const Reference& r : references()) {
    const TestResult w = brown_forsythe(r.a, r.b);
    EXPECT_NEAR(w.statistic, r.w, tolerance(r.w));
    EXPECT_DOUBLE_EQ(w.df, static_cast<double>(r.a.size() + r.b.size() - 2));
    EXPECT_NEAR(w.p_value, r.w_p, tolerance(r.w_p));
  }
}

TEST(Statistics, HolmMatchesStatsmodels) {
  // multipletests(p, method="holm")[1]
  const std::vector<double> p = {0.01, 0.04, 0.03, 0.005, 0.2, 0.5};
  const std::vector<double> want = {0.05, 0.12, 0.12, 0.03, 0.4, 0.5};
  const std::vector<double> got = holm(p);
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) EXPECT_NEAR(got[i], want[i], 1e-15) << i;
  const std::vector<double> tied = holm(std::vector<double>{0.02, 0.02, 0.3});
  EXPECT_NEAR(tied[0], 0.06, 1e-15);
  EXPECT_NEAR(tied[1], 0.06, 1e-15);
  EXPECT_NEAR(tied[2], 0.3, 1e-15);
}

TEST(Statistics, HolmLeavesUndefinedTestsOutOfTheFamily) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> got = holm(std::vector<double>{0.01, nan, 0.04});
  EXPECT_NEAR(got[0], 0.02, 1e-15);   // a family of two, not three
  EXPECT_TRUE(std::isnan(got[1]));
  EXPECT_NEAR(got[2], 0.04, 1e-15);
}

TEST(Statistics, ComparisonsAdjustEachTestOverTheFamily) {
  const std::vector<std::vector<double>> samples = {references()[0].a, references()[0].b, references()[3].a};
  const auto pairs = all_pairs(samples.size());
  ASSERT_EQ(pairs.size(), 3U);
  const std::vector<Comparison> cs = compare(samples, pairs);
  std::vector<double> welch_p, mw_p, bf_p;
  for (const Comparison& c : cs) {
    EXPECT_EQ(c.welch.p_value, welch_t_test(samples[c.a], samples[c.b]).p_value);
    EXPECT_EQ(c.a12, vargha_delaney_a12(samples[c.a], samples[c.b]));
    EXPECT_EQ(c.spread.p_value, brown_forsythe(samples[c.a], samples[c.b]).p_value);
    EXPECT_DOUBLE_EQ(c.sd_ratio, summarise(samples[c.a]).sd / summarise(samples[c.b]).sd);
    welch_p.push_back(c.welch.p_value);
    mw_p.push_back(c.mann_whitney.p_value);
    bf_p.push_back(c.spread.p_value);
  }
  const std::vector<double> wh = holm(welch_p), mh = holm(mw_p), bh = holm(bf_p);
  for (std::size_t k = 0; k < cs.size(); ++k) {
    EXPECT_EQ(cs[k].welch_p_holm, wh[k]);
    EXPECT_EQ(cs[k].mann_whitney_p_holm, mh[k]);
    EXPECT_EQ(cs[k].spread_p_holm, bh[k]);
    EXPECT_GE(cs[k].welch_p_holm, cs[k].welch.p_value);
  }
}

// Runs that all end the same way but for the last bits of their fitness have no spread to
// compare: the ratio is undefined, not 1e14.
TEST(Statistics, AnSdRatioOverRoundingIsUndefined) {
  const std::vector<std::vector<double>> samples = {{4000.0, 4100.0, 4200.0},
                                                    {5000.0, std::nextafter(5000.0, 6000.0), 5000.0}};
  const std::vector<std::pair<std::size_t, std::size_t>> pairs = {{0, 1}, {1, 0}};
  const std::vector<Comparison> cs = compare(samples, pairs);
  EXPECT_TRUE(std::isnan(cs[0].sd_ratio));
  EXPECT_DOUBLE_EQ(cs[1].sd_ratio, summarise(samples[1]).sd / summarise(samples[0]).sd);
}

TEST(Statistics, UndefinedTestsGiveNaN) {
  const std::vector<double> one = {1.0};
  const std::vector<double> flat = {2.0, 2.0, 2.0};
  EXPECT_TRUE(std::isnan(welch_t_test(one, flat).p_value));
  EXPECT_TRUE(std::isnan(welch_t_test(flat, flat).p_value));
  EXPECT_TRUE(std::isnan(mann_whitney_u(flat, flat).p_value));
  EXPECT_TRUE(std::isnan(mann_whitney_u({}, flat).p_value));
  EXPECT_TRUE(std::isnan(welch_t_test(one, flat).statistic));   // never a number for an undefined test
  EXPECT_TRUE(std::isnan(brown_forsythe(one, flat).p_value));
  EXPECT_TRUE(std::isnan(brown_forsythe(flat, flat).p_value));
  // Two values per sample: each sample's two deviations from its median are equal.
  EXPECT_TRUE(std::isnan(brown_forsythe(std::vector<double>{1.1, 1.7}, std::vector<double>{3.3, 9.1}).p_value));
  EXPECT_TRUE(std::isnan(vargha_delaney_a12({}, flat)));
  // Identical samples with spread: no difference at all.
  const std::vector<double> x = {1, 2, 3, 4};
  EXPECT_NEAR(welch_t_test(x, x).p_value, 1.0, 1e-12);
  EXPECT_NEAR(mann_whitney_u(x, x).p_value, 1.0, 1e-12);
}


// Fisher's exact test and the censored Mann-Whitney test of evaluations to success, against
// SciPy 1.10.1:
//   stats.fisher_exact([[sa, fa], [sb, fb]])                             odds ratio, p
//   stats.mannwhitneyu(a', b', alternative="two-sided", method="auto")   U, p
// where a' and b' hold every run that never succeeded as budget + 1 (Gehan's test with one
// censoring point).
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double p_tolerance(double v) { return 1e-15 + 1e-9 * std::fabs(v); }

struct FisherReference {
  std::size_t sa, fa, sb, fb;
  double odds_ratio, p;
};

TEST(SuccessStatistics, FisherMatchesScipy) {
  const std::vector<FisherReference> references = {
      {3, 37, 15, 25, 0.13513513513513514, 0.0025343227490509683},
      {39, 1, 3, 37, 481.0, 8.131566341457106e-18},   // the paper's hard maze: novelty vs fitness
      {0, 10, 10, 0, 0.0, 1.082508822446903e-05},
      {1, 9, 11, 3, 0.030303030303030304, 0.0027594561852200836},
      {5, 5, 5, 5, 1.0, 1.0},
      {2, 8, 8, 2, 0.0625, 0.023014137565221155},     // symmetric: its mirror table ties it
      {0, 5, 0, 5, kNaN, 1.0},                        // nobody succeeded: an empty column
      {7, 0, 3, 4, kInf, 0.06993006993006992},
      {12, 28, 11, 29, 1.12987012987013, 1.0},
      {20, 20, 20, 20, 1.0, 1.0},
      {1, 39, 0, 40, kInf, 1.0},
      {40, 0, 36, 4, kInf, 0.11556797632746997},
  };
  for (const FisherReference& r : references) {
    const FisherResult f = fisher_exact(r.sa, r.fa, r.sb, r.fb);
    SCOPED_TRACE(::testing::Message() << r.sa << " " << r.fa << " " << r.sb << " " << r.fb);
    EXPECT_NEAR(f.p_value, r.p, p_tolerance(r.p));
    if (std::isnan(r.odds_ratio)) EXPECT_TRUE(std::isnan(f.odds_ratio));
    else if (std::isinf(r.odds_ratio)) EXPECT_EQ(f.odds_ratio, kInf);
    else EXPECT_NEAR(f.odds_ratio, r.odds_ratio, p_tolerance(r.odds_ratio));
  }
}

TEST(SuccessStatistics, FisherIsTheSameWhicheverSampleComesFirst) {
  for (const auto& [sa, fa, sb, fb] : std::vector<std::array<std::size_t, 4>>{{3, 37, 15, 25}, {7, 0, 3, 4}}) {
    EXPECT_NEAR(fisher_exact(sa, fa, sb, fb).p_value, fisher_exact(sb, fb, sa, fa).p_value, 1e-15);
    EXPECT_NEAR(fisher_exact(sa, fa, sb, fb).p_value, fisher_exact(fa, sa, fb, sb).p_value, 1e-15);
  }
}

struct CensoredReference {
  std::vector<std::optional<double>> a, b;
  double budget, u, p;
};

TEST(SuccessStatistics, CensoredMannWhitneyMatchesScipyWithUnsolvedRunsAtTheBudgetPlusOne) {
  const auto none = std::nullopt;
  const std::vector<CensoredReference> references = {
      {{1200, 3400, none, 560, none, 8800, 2100, none}, {none, none, 9100, none, 7700, none, none, none}, 10000,
       16.0, 0.07284885832099199},
      // Every run succeeded, no ties: SciPy's "auto" is exact here, and so is esc.
      {{250, 500, 750, 1000, 1250}, {1500, 1750, 2000, 2250, 2500, 2750}, 3000, 0.0, 0.004329004329004329},
      // 40-run-sized samples in the paper's budget: 10 of 13 and 2 of 13 unsolved.
      {{none, none, none, none, none, none, none, none, none, none, 120000, 64000, 230000},
       {35109, 12000, 88000, none, 41000, 230500, 77000, 150000, 9000, none, 190000, 61000, 100000}, 250000, 143.0,
       0.0017398324714854186},
      {{100, none}, {200, 300, none, none, 400}, 450, 4.0, 0.8407304470798855},
  };
  for (const CensoredReference& r : references) {
    const TestResult t = censored_mann_whitney(r.a, r.b, r.budget);
    EXPECT_EQ(t.statistic, r.u);
    EXPECT_NEAR(t.p_value, r.p, p_tolerance(r.p));
  }
  // Nobody succeeded: every value tied, no p (SciPy says 1; esc's Mann-Whitney has no
  // variance to divide by, as for any all-equal samples).
  const std::vector<std::optional<double>> unsolved(3), unsolved_too(4);
  EXPECT_TRUE(std::isnan(censored_mann_whitney(unsolved, unsolved_too, 5000).p_value));
}

TEST(SuccessStatistics, ARunNeverCountsBelowAnObservedSuccess) {
  // A budget below an observed value (none is made so) is raised: the unsolved run stays last.
  const std::vector<std::optional<double>> a{std::nullopt}, b{700.0};
  EXPECT_EQ(censored_mann_whitney(a, b, 500).statistic, 1.0);   // a's unsolved run beats b's
}

}  // namespace
}  // namespace esc::report
