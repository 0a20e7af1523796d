// `success when ...` in the run loop: which evaluation of a run first passed the test,
// counted over the run's generations (candidates in ask order, from 1), read as the script
// declares the value (a minimised objective not negated), kept by a run that resumes.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "runtime/eval/campaign.hpp"
#include "runtime/eval/campaign_parts.hpp"
#include "runtime/eval/success.hpp"
#include "tests/eval/campaign_checks.hpp"
#include "tests/eval/test_experiment.hpp"

namespace esc::eval {
namespace {

using Of = SuccessSpec::Of;
using Check = SuccessSpec::Test;

ExperimentSpec with_test(Check test, double threshold) {
  ExperimentSpec spec = testing::small_experiment();
  spec.success = SuccessSpec{spec.fitness.name, Of::Objective, 0, test, threshold};
  return spec;
}

// Tells `job` one generation whose candidates measured `fitness` (by index; 0 elsewhere).
void tell(detail::RunJob& job, const std::map<std::size_t, double>& fitness) {
  const std::size_t n = job.breed();
  std::vector<evo::Outcome> outcomes(n, evo::Outcome{{0.0}, {}});
  std::vector<double> values(n, 0.0);
  for (const auto& [i, f] : fitness) outcomes.at(i).objectives[0] = values.at(i) = f;
  job.evaluated(outcomes, detail::summarise(job.generation(), values, 0, 0.0));
}

TEST(Success, TheFirstPassingEvaluationCountsEveryEarlierGenerationAndCandidate) {
  const ExperimentSpec spec = with_test(Check::Above, 0.5);
  detail::RunJob job(spec, spec.controllers.front(), 0, nullptr);
  ASSERT_EQ(job.evaluations_per_generation(), 20u);   // lambda
  tell(job, {{3, 0.5}});                              // 0.5 is not above 0.5
  EXPECT_FALSE(job.state().success_evaluation.has_value());
  tell(job, {{12, 2.0}, {7, 1.0}});                   // candidates 7 and 12 of generation 1 pass
  EXPECT_EQ(job.state().success_evaluation, 20 + 7 + 1);
  tell(job, {{0, 5.0}});                              // a later success changes nothing
  EXPECT_EQ(job.state().success_evaluation, 28);
}

TEST(Success, AMinimisedObjectiveIsTestedAsMeasuredAndADescriptorAsReduced) {
  ExperimentSpec spec = testing::small_experiment();
  spec.objectives = {{"avoid", false, std::nullopt}, {"energy", true, DeclaredRange{0, 10}}};
  spec.further = {spec.fitness};
  spec.further.front().name = "energy";
  spec.descriptors = {{"x", {}, {}, false, Reduction::Last, {0, 1}}};
  const evo::Outcome o{{3.0, -2.0}, {0.25}};   // optimizers are told -energy
  const SuccessSpec energy{"energy", Of::Objective, 1, Check::AtMost, 2.0};
  EXPECT_EQ(tested_value(spec, energy, o), 2.0);
  EXPECT_TRUE(energy.passes(tested_value(spec, energy, o)));
  const SuccessSpec x{"x", Of::Descriptor, 0, Check::Below, 0.3};
  EXPECT_EQ(tested_value(spec, x, o), 0.25);
  spec.success = x;
  const std::vector<evo::Outcome> outcomes{{{0.0, 0.0}, {0.5}}, o, o};
  EXPECT_EQ(first_success(spec, outcomes), 1u);
  spec.success.reset();
  EXPECT_FALSE(first_success(spec, outcomes).has_value());
}

TEST(Success, AFitnessAlwaysAboveTheThresholdSucceedsAtTheFirstEvaluation) {
  // The fitness, max(forward_speed, 0) (1 - sqrt(wheel_diff)), is never negative.
  CampaignListener quiet;
  const CampaignResult always = run_campaign(with_test(Check::AtLeast, 0.0), {2}, quiet);
  EXPECT_EQ(always.success, "avoid >= 0");
  for (const RunResult& r : always.controllers.front().runs) EXPECT_EQ(r.success_evaluation, 1);
  const SuccessCount count = count_successes(always.controllers.front().runs);
  EXPECT_EQ(count.successes, 2u);
  EXPECT_EQ(count.median_evaluations, 1.0);

  const CampaignResult never = run_campaign(with_test(Check::Below, 0.0), {2}, quiet);
  for (const RunResult& r : never.controllers.front().runs) EXPECT_FALSE(r.success_evaluation.has_value());
  EXPECT_TRUE(std::isnan(count_successes(never.controllers.front().runs).median_evaluations));

  // Without a test, nothing is counted and the results are those of the tested runs.
  const CampaignResult plain = run_campaign(testing::small_experiment(), {2}, quiet);
  EXPECT_TRUE(plain.success.empty());
  for (const RunResult& r : plain.controllers.front().runs) EXPECT_FALSE(r.success_evaluation.has_value());
  for (std::size_t r = 0; r < plain.controllers.front().runs.size(); ++r)
    EXPECT_EQ(plain.controllers.front().runs[r].best_genome, always.controllers.front().runs[r].best_genome);
}

TEST(Success, AResumedRunCountsOnWhereItStopped) {
  CampaignListener quiet;
  const CampaignResult plain = run_campaign(testing::small_experiment(), {2}, quiet);
  // Met first in a later generation of run 1: its generation-3 best.
  const ExperimentSpec spec = with_test(Check::AtLeast, plain.controllers[0].runs[1].generations[3].best);
  const CampaignResult whole = run_campaign(spec, {2}, quiet);
  const auto met = whole.controllers[0].runs[1].success_evaluation;
  ASSERT_TRUE(met.has_value());
  EXPECT_GT(*met, 20);   // not in generation 0: the count crosses generations
  EXPECT_LE(*met, 4 * 20);
  testing::expect_resumes_to(spec, whole, {0, 2, 4});
}

}  // namespace
}  // namespace esc::eval
