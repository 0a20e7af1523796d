// Roles (docs/groups.md): `roles N` evolves N networks as one genome, role r's weights its
// r-th slice, driving robots r, r + N, ... Two equal roles are the clonal team to the bit;
// robots too far apart to meet each drive as their role's clonal team drives them.
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "runtime/core/rng.hpp"
#include "runtime/eval/campaign.hpp"
#include "runtime/eval/evaluator.hpp"
#include "tests/eval/test_experiment.hpp"

namespace esc::eval {
namespace {

struct Quiet final : CampaignListener {};

struct Collect final : TraceSink {
  std::vector<TraceStep> steps;
  void on_step(const TraceStep& t) override { steps.push_back(t); }
};

// Four robots a metre apart in a 3 m square, far from its walls and obstacles (in a corner),
// for epochs too short to bring any two within sensing range.
ExperimentSpec apart(int roles) {
  ExperimentSpec spec = testing::small_experiment();
  spec.arena.width_m = 3.0;
  spec.arena.height_m = 3.0;
  spec.robots = 4;
  spec.roles = roles;
  spec.epochs = 2;
  spec.steps = 25;
  spec.formation.kind = sim::FormationKind::At;
  spec.formation.at = {{1.0, 1.0, 0.0}, {2.0, 1.0, 1.5}, {1.0, 2.0, 3.0}, {2.0, 2.0, 4.5}};
  return spec;
}

std::vector<double> random_weights(std::size_t n, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<double> w(n);
  for (double& g : w) g = rng.uniform(-2.0, 2.0);
  return w;
}

std::vector<TraceStep> trace(const ExperimentSpec& spec, const std::vector<double>& genome) {
  Evaluator evaluator(spec);
  Collect rows;
  (void)evaluator.evaluate(spec.controllers.front(), genome, 5, &rows);
  return rows.steps;
}

std::vector<double> joined(std::vector<double> a, const std::vector<double>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

TEST(Roles, AGenomeHoldsEveryRolesWeights) {
  const ExperimentSpec spec = apart(2);
  const control::ControllerSpec& c = spec.controllers.front();
  EXPECT_EQ(spec.genome_length(c), 2 * c.genome_size());
  EXPECT_EQ(spec.problem_of(c).genome_size, 2 * c.genome_size());
  EXPECT_EQ(spec.genome_size_of(c), 2 * c.genome_size());
  Evaluator evaluator(spec);
  EXPECT_THROW((void)evaluator.evaluate(c, random_weights(c.genome_size(), 1), 5), std::invalid_argument);
}

TEST(Roles, TwoEqualRolesAreTheClonalTeam) {
  const ExperimentSpec clonal = apart(1);
  const std::vector<double> a = random_weights(clonal.controllers.front().genome_size(), 1);
  ExperimentSpec roles = apart(2);
  roles.formation.at = {{0.3, 0.3, 0.0}, {0.42, 0.3, 1.5}, {0.3, 0.42, 3.0}, {0.42, 0.42, 4.5}};   // crowded
  ExperimentSpec crowded = clonal;
  crowded.formation.at = roles.formation.at;
  const Evaluation one = Evaluator(crowded).evaluate(crowded.controllers.front(), a, 5);
  const Evaluation two = Evaluator(roles).evaluate(roles.controllers.front(), joined(a, a), 5);
  EXPECT_EQ(one.fitness, two.fitness);
  EXPECT_EQ(one.steps, two.steps);
}

TEST(Roles, EachRoleDrivesItsOwnRobots) {
  const ExperimentSpec clonal = apart(1);
  const std::size_t n = clonal.controllers.front().genome_size();
  const std::vector<double> a = random_weights(n, 1), b = random_weights(n, 2);
  const std::vector<TraceStep> as_a = trace(clonal, a), as_b = trace(clonal, b), both = trace(apart(2), joined(a, b));
  ASSERT_EQ(both.size(), as_a.size());
  ASSERT_EQ(both.size(), as_b.size());
  std::size_t differ = 0;
  for (std::size_t i = 0; i < both.size(); ++i) {
    const TraceStep& own = both[i].robot % 2 == 0 ? as_a[i] : as_b[i];
    ASSERT_EQ(both[i].robot, own.robot);
    EXPECT_EQ(both[i].pose.x_m, own.pose.x_m) << "row " << i;
    EXPECT_EQ(both[i].pose.y_m, own.pose.y_m) << "row " << i;
    EXPECT_EQ(both[i].left_command, own.left_command) << "row " << i;
    EXPECT_EQ(both[i].right_command, own.right_command) << "row " << i;
    differ += both[i].robot % 2 == 1 && both[i].pose.x_m != as_a[i].pose.x_m;
  }
  EXPECT_GT(differ, both.size() / 4) << "role 1's robots should not drive as role 0's";
}

TEST(Roles, ARunEvolvesEveryRoleAndIsBitIdenticalForAnyThreadCount) {
  ExperimentSpec spec = testing::small_experiment();
  spec.arena.width_m = 0.8;
  spec.arena.height_m = 0.6;
  spec.robots = 4;
  spec.roles = 2;
  spec.generations = 3;
  Quiet quiet;
  const CampaignResult one = run_campaign(spec, {1}, quiet);
  const CampaignResult two = run_campaign(spec, {2}, quiet);
  EXPECT_EQ(one.roles, 2);
  const auto& a = one.controllers.front().runs;
  const auto& b = two.controllers.front().runs;
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t r = 0; r < a.size(); ++r) {
    EXPECT_EQ(a[r].best_genome.size(), 2 * spec.controllers.front().genome_size());
    EXPECT_EQ(a[r].best_genome, b[r].best_genome);
    EXPECT_EQ(a[r].best_fitness, b[r].best_fitness);
  }
}

}  // namespace
}  // namespace esc::eval
