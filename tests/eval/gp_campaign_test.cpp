// Genetic programming in the campaign: a GP run is the same for any thread count, it
// improves on its initial population, it continues bit for bit from the state after any
// generation (and from nothing but a GP population), its best tree replays to its best
// fitness, and adding tree controllers to an experiment leaves its networks' ES runs
// untouched.
#include <gtest/gtest.h>

#include <variant>

#include "runtime/eval/campaign.hpp"
#include "runtime/genome/tree/codec.hpp"
#include "runtime/genome/tree/print.hpp"
#include "tests/eval/campaign_checks.hpp"
#include "tests/eval/gp_experiment.hpp"
#include "tests/algorithm_settings.hpp"

namespace esc::eval {
namespace {

using testing::expect_same;
using testing::Snapshotter;

TEST(GpCampaign, SameResultsForOneTwoAndThreeThreads) {
  const ExperimentSpec spec = testing::gp_experiment();
  CampaignListener quiet;
  const CampaignResult one = run_campaign(spec, {1}, quiet);
  ASSERT_EQ(one.controllers.size(), 2u);
  EXPECT_EQ(one.controllers[0].architecture, "tree wheels");
  EXPECT_EQ(one.controllers[0].genome_size, 40u);
  EXPECT_EQ(one.controllers[1].choices, (std::vector<std::string>{"forward", "left", "right"}));
  for (const ControllerResult& c : one.controllers)
    for (const RunResult& r : c.runs) {
      EXPECT_EQ(r.generations.size(), 6u);
      EXPECT_EQ(r.generations[0].evaluations, 24);
      EXPECT_FALSE(r.best_tree.empty());
    }
  expect_same(one, run_campaign(spec, {2}, quiet));
  expect_same(one, run_campaign(spec, {3}, quiet));
}

TEST(GpCampaign, ObstacleAvoidanceImprovesOnTheInitialPopulation) {
  const ExperimentSpec spec = testing::gp_experiment();
  CampaignListener quiet;
  const CampaignResult res = run_campaign(spec, {2}, quiet);
  for (const ControllerResult& c : res.controllers) {
    double first_mean = 0.0, last_mean = 0.0;
    for (const RunResult& r : c.runs) {
      EXPECT_GT(r.best_fitness, r.generations.front().best) << c.name << " run " << r.run;
      first_mean += r.generations.front().mean;
      last_mean += r.generations.back().mean;
    }
    EXPECT_GT(last_mean, first_mean) << c.name << ": the population's mean fitness did not improve";
  }
}

TEST(GpCampaign, ContinuingFromAnyGenerationIsBitIdentical) {
  ExperimentSpec spec = testing::gp_experiment();
  gp_of(spec).generations = 5;
  CampaignListener quiet;
  const CampaignResult whole = run_campaign(spec, {2}, quiet);
  for (int at : {0, 2, 4}) {
    Snapshotter snap;
    snap.at = at;
    (void)run_campaign(spec, {1}, snap);
    ASSERT_EQ(snap.states.size(), static_cast<std::size_t>(2 * spec.runs));
    ResumePoint point;
    point.finished.push_back({spec.controllers[0].name, whole.controllers[0].runs[0]});
    for (const auto& s : snap.states)
      if (!(s.controller == spec.controllers[0].name && s.state.run == 0)) point.in_progress.push_back(s);
    for (const auto& s : point.in_progress)
      EXPECT_EQ(s.state.optimizer.algorithm, "gp");
    CampaignListener none;
    expect_same(whole, run_campaign(spec, {2, &point}, none));
  }
}

TEST(GpCampaign, TheBestTreeReplaysToTheBestFitness) {
  const ExperimentSpec spec = testing::gp_experiment();
  Snapshotter rec;
  rec.at = -1;
  const CampaignResult res = run_campaign(spec, {2, nullptr, true}, rec);
  ASSERT_EQ(rec.traces.size(), 4u);
  Evaluator evaluator(spec);
  for (std::size_t k = 0; k < rec.traces.size(); ++k) {
    const auto& [run, trace] = rec.traces[k];
    const control::ControllerSpec& c = spec.controllers[k / 2];
    ASSERT_FALSE(trace.empty());
    EXPECT_EQ(trace.back().fitness, run.best_fitness);
    // The stored genome is the tree: decoded and evaluated on its stream, the same fitness.
    const genome::tree::Tree tree = genome::tree::decode(run.best_genome, *c.primitives);
    EXPECT_EQ(genome::tree::to_script(tree, *c.primitives), run.best_tree);
    const std::uint64_t seed = evaluation_seed(run.seed, run.best_generation, static_cast<std::size_t>(run.best_index));
    EXPECT_EQ(evaluator.evaluate(c, run.best_genome, seed).fitness, run.best_fitness);
    if (c.head == control::Head::Symbolic) {
      ASSERT_EQ(run.action_usage.size(), 3u);
      std::int64_t steps = 0;
      for (std::int64_t n : run.action_usage) steps += n;
      EXPECT_EQ(steps, static_cast<std::int64_t>(trace.size()));
      for (const TraceStep& t : trace) EXPECT_TRUE(t.action >= 0 && t.action < 3);
    } else {
      EXPECT_TRUE(run.action_usage.empty());
      for (const TraceStep& t : trace) EXPECT_EQ(t.action, -1);
    }
  }
}

TEST(GpCampaign, TreesBesideNetworksLeaveTheEsRunsUntouched) {
  const ExperimentSpec es_only = testing::small_experiment();
  ExperimentSpec mixed = testing::gp_experiment();
  mixed.controllers.insert(mixed.controllers.begin(), es_only.controllers.front());
  gp_of(mixed).generations = 2;
  CampaignListener quiet;
  const CampaignResult a = run_campaign(es_only, {2}, quiet);
  const CampaignResult b = run_campaign(mixed, {2}, quiet);
  ASSERT_EQ(b.controllers.size(), 3u);
  CampaignResult b_es = b;
  b_es.controllers.resize(1);
  expect_same(a, b_es);
  EXPECT_EQ(b.controllers[0].runs[0].generations.size(), 6u);   // the ES's generations
  EXPECT_EQ(b.controllers[1].runs[0].generations.size(), 2u);   // the GP's
  EXPECT_EQ(mixed.total_generations(), 2 * (6 + 2 + 2));
}

// What a run continues from is its optimizer's state: the ES's for a network, GP's for a
// tree; the other one's is refused, not misread.
TEST(GpCampaign, AStateOfTheOtherAlgorithmIsRefused) {
  ExperimentSpec mixed = testing::gp_experiment();
  mixed.controllers.insert(mixed.controllers.begin(), testing::small_experiment().controllers.front());
  CampaignListener quiet;
  for (std::size_t k : {0u, 1u}) {   // the network given trees, the Wheels tree given parents
    RunState st;
    st.generations.push_back({0, 1.0, 0.5, 0.1, 24, 100, 0.0});
    st.optimizer = {k == 0 ? "gp" : "es", 1, {}};
    ResumePoint point;
    point.in_progress.push_back({mixed.controllers[k].name, st});
    try {
      (void)run_campaign(mixed, {1, &point}, quiet);
      ADD_FAILURE() << "resumed " << mixed.controllers[k].name << " from the other algorithm's state";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(k == 0 ? "was saved by gp (format 1), not by es (format 1)"
                                                  : "was saved by es (format 1), not by gp (format 1)"),
                std::string::npos)
          << e.what();
    }
  }
}

TEST(GpCampaign, ATreeWithoutGpSettingsIsRefused) {
  ExperimentSpec spec = testing::gp_experiment();
  spec.algorithm_settings.erase(eval::ExperimentSpec::kTreeOperators);
  CampaignListener quiet;
  EXPECT_THROW((void)run_campaign(spec, {1}, quiet), std::invalid_argument);
}

}  // namespace
}  // namespace esc::eval
