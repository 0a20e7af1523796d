#include "runtime/eval/evaluator.hpp"

#include <gtest/gtest.h>

#include "runtime/core/rng.hpp"
#include "runtime/eval/observe.hpp"
#include "tests/eval/test_experiment.hpp"

namespace esc::eval {
namespace {

std::vector<double> random_genome(std::size_t n, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<double> g(n);
  for (double& x : g) x = rng.uniform(-1.0, 1.0);
  return g;
}

TEST(Evaluator, SameSeedSameFitnessWhateverRanBefore) {
  const ExperimentSpec spec = testing::small_experiment();
  const auto& c = spec.controllers.front();
  const auto a = random_genome(c.genome_size(), 1);
  const auto b = random_genome(c.genome_size(), 2);
  Evaluator fresh(spec);
  const Evaluation first = fresh.evaluate(c, a, 99);
  Evaluator reused(spec);
  (void)reused.evaluate(c, b, 5);
  (void)reused.evaluate(c, b, 6);
  const Evaluation again = reused.evaluate(c, a, 99);
  EXPECT_EQ(first.fitness, again.fitness);   // bit-identical, not merely close
  EXPECT_EQ(first.steps, again.steps);
}

TEST(Evaluator, DifferentSeedsGiveDifferentStartPoses) {
  const ExperimentSpec spec = testing::small_experiment();
  const auto& c = spec.controllers.front();
  // Zero weights but positive output biases: the robot drives straight until it hits
  // something, so the fitness measures the free run ahead of the start pose.
  std::vector<double> a(c.genome_size(), 0.0);
  const std::size_t outputs_first = (spec.controllers.front().mlp.inputs.size() + 1) * 4;
  a[outputs_first] = 1.0;       // left wheel bias
  a[outputs_first + 5] = 1.0;   // right wheel bias (4 hidden inputs + bias per neuron)
  Evaluator ev(spec);
  const double f1 = ev.evaluate(c, a, 1).fitness;
  const double f2 = ev.evaluate(c, a, 2).fitness;
  EXPECT_GT(f1, 0.0);
  EXPECT_NE(f1, f2);
}

TEST(Evaluator, TheNoiseObservableIsWrittenWhereAProgramOrANetworkReadsIt) {
  ExperimentSpec spec = testing::small_experiment();
  const control::ControllerSpec plain = spec.controllers.front();
  EXPECT_FALSE(reads_slot(spec.fitness, plain, expr::slot::noise));
  control::ControllerSpec hearing = plain;
  hearing.mlp.inputs.push_back(expr::slot::noise);
  EXPECT_TRUE(reads_slot(spec.fitness, hearing, expr::slot::noise));
  // A fitness of `noise` alone: uniform in [0, 1) at every step, so its sum is near half
  // the steps (it would be 0 if the step loop left the slot unwritten).
  spec.fitness.step = testing::load(expr::slot::noise);
  EXPECT_TRUE(reads_slot(spec.fitness, plain, expr::slot::noise));
  Evaluator ev(spec);
  const auto e = ev.evaluate(plain, random_genome(plain.genome_size(), 3), 3);
  EXPECT_GT(e.fitness, 0.25 * static_cast<double>(e.steps));
  EXPECT_LT(e.fitness, 0.75 * static_cast<double>(e.steps));
}

TEST(Evaluator, StepsAreBoundedByEpochsTimesSteps) {
  const ExperimentSpec spec = testing::small_experiment();
  const auto& c = spec.controllers.front();
  Evaluator ev(spec);
  for (std::uint64_t s = 0; s < 10; ++s) {
    const auto e = ev.evaluate(c, random_genome(c.genome_size(), s), s);
    EXPECT_GE(e.steps, spec.epochs);   // every epoch runs at least one step
    EXPECT_LE(e.steps, static_cast<std::int64_t>(spec.epochs) * spec.steps);
    // The forward-only term is at most 1 per step.
    EXPECT_LE(e.fitness, static_cast<double>(e.steps) + 1e-9);
    EXPECT_GE(e.fitness, 0.0);
  }
}

TEST(Evaluator, FitnessIsLinearInItsTermsOnAFixedTrajectory) {
  // The trajectory does not depend on the fitness (no stop condition), so the fitness of
  // `forward_speed + 0.5 * ir[0]` equals F(forward_speed) + 0.5 F(ir[0]) on the same seed.
  ExperimentSpec spec = testing::small_experiment();
  spec.fitness.stop_when.clear();
  const auto& c = spec.controllers.front();
  const auto g = random_genome(c.genome_size(), 11);
  Evaluator ev(spec);
  spec.fitness.step = testing::load(expr::slot::forward_speed);
  const double a = ev.evaluate(c, g, 3).fitness;
  spec.fitness.step = testing::load(expr::slot::ir);
  const double b = ev.evaluate(c, g, 3).fitness;
  expr::Program sum;
  sum.push_load(expr::slot::forward_speed);
  sum.push_const(0.5);
  sum.push_load(expr::slot::ir);
  sum.push_op(expr::Op::Mul);
  sum.push_op(expr::Op::Add);
  spec.fitness.step = sum;
  const double ab = ev.evaluate(c, g, 3).fitness;
  EXPECT_GT(b, 0.0);   // the trajectory came near something
  EXPECT_NEAR(ab, a + 0.5 * b, 1e-9 * (1.0 + std::abs(ab)));
}

}  // namespace
}  // namespace esc::eval
