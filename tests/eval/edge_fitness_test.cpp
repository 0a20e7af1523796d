// Fitness at the edge of the numbers: the sum of step terms saturates at +-1e300 and NaN
// is the lowest fitness; a generation counts its saturated evaluations; mean and sd stay
// finite for every finite sample and are unchanged where the plain formulas are finite.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "runtime/eval/campaign_parts.hpp"
#include "runtime/eval/evaluator.hpp"
#include "runtime/eval/moments.hpp"
#include "tests/eval/test_experiment.hpp"

namespace esc::eval {
namespace {

Evaluation with_constant_term(double term) {
  ExperimentSpec spec = testing::small_experiment();
  spec.fitness.step = expr::Program::constant(term);
  const auto& c = spec.controllers.front();
  Evaluator ev(spec);
  return ev.evaluate(c, std::vector<double>(c.genome_size(), 0.0), 7);
}

double fitness_of_constant_term(double term) { return with_constant_term(term).fitness; }

TEST(EdgeFitness, TheSumSaturatesInsteadOfReachingInfinity) {
  EXPECT_EQ(fitness_of_constant_term(1e308), expr::kSaturation);    // two steps already overflow
  EXPECT_EQ(fitness_of_constant_term(-1e308), -expr::kSaturation);
  EXPECT_EQ(fitness_of_constant_term(std::numeric_limits<double>::quiet_NaN()), -expr::kSaturation);
  const Evaluation plain = with_constant_term(0.5);   // within the limits: the plain sum
  EXPECT_EQ(plain.fitness, 0.5 * static_cast<double>(plain.steps));
}

TEST(EdgeFitness, AGenerationCountsItsSaturatedEvaluationsAndKeepsFiniteStatistics) {
  const std::vector<double> fitness{1e300, 3.0, -1e300, 1e300};
  const GenerationStats g = detail::summarise(4, fitness, 100, 0.5);
  EXPECT_EQ(g.saturated, 3);
  EXPECT_EQ(g.best, 1e300);
  EXPECT_TRUE(std::isfinite(g.mean));
  EXPECT_TRUE(std::isfinite(g.sd));
  EXPECT_NEAR(g.mean / 1e300, 0.25, 1e-12);
  // Deviations from the mean 0.25e300: 0.75, -0.25 (3 is nothing beside it), -1.25, 0.75.
  EXPECT_NEAR(g.sd / 1e300, std::sqrt((2 * 0.75 * 0.75 + 0.25 * 0.25 + 1.25 * 1.25) / 3.0), 1e-12);
}

TEST(Moments, AreThePlainTwoPassFormulasBitForBitWhereThoseAreFinite) {
  const std::vector<double> x{0.1, 2.5, -3.25, 7.0, 1e-3};
  double sum = 0.0;
  for (double v : x) sum += v;
  const double mean = sum / 5.0;
  double sq = 0.0;
  for (double v : x) sq += (v - mean) * (v - mean);
  const Moments m = moments(x);
  EXPECT_EQ(m.mean, mean);
  EXPECT_EQ(m.sd, std::sqrt(sq / 4.0));
  EXPECT_EQ(moments(std::vector<double>{4.0}).sd, 0.0);
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(std::isnan(moments(std::vector<double>{1.0, inf}).mean));   // n/a, not inf
  const std::vector<double> huge(1000, 1.7e308);
  EXPECT_NEAR(moments(huge).mean, 1.7e308, 1e294);
  EXPECT_EQ(moments(huge).sd, 0.0);
}

}  // namespace
}  // namespace esc::eval
