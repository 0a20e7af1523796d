#include "runtime/eval/campaign.hpp"

#include <algorithm>
#include <span>
#include <vector>

#include <gtest/gtest.h>

#include "tests/eval/campaign_checks.hpp"
#include "tests/eval/test_experiment.hpp"
#include "tests/algorithm_settings.hpp"

namespace esc::eval {
namespace {

struct Recorder final : CampaignListener {
  int generations = 0;
  int runs = 0;
  void generation_done(const control::ControllerSpec&, int, const GenerationStats&) override { ++generations; }
  void run_done(const control::ControllerSpec&, const RunResult&) override { ++runs; }
};

CampaignResult run_with_threads(const ExperimentSpec& spec, int threads) {
  Recorder r;
  return run_campaign(spec, {threads}, r);
}

TEST(Campaign, BitIdenticalForAnyThreadCount) {
  const ExperimentSpec spec = testing::small_experiment();
  const CampaignResult one = run_with_threads(spec, 1);
  const CampaignResult two = run_with_threads(spec, 2);
  const CampaignResult four = run_with_threads(spec, 4);
  for (const CampaignResult* other : {&two, &four}) {
    ASSERT_EQ(one.controllers.size(), other->controllers.size());
    for (std::size_t c = 0; c < one.controllers.size(); ++c) {
      const auto& ra = one.controllers[c].runs;
      const auto& rb = other->controllers[c].runs;
      ASSERT_EQ(ra.size(), rb.size());
      for (std::size_t r = 0; r < ra.size(); ++r) {
        EXPECT_EQ(ra[r].best_fitness, rb[r].best_fitness);
        EXPECT_EQ(ra[r].best_genome, rb[r].best_genome);
        ASSERT_EQ(ra[r].generations.size(), rb[r].generations.size());
        for (std::size_t g = 0; g < ra[r].generations.size(); ++g) {
          EXPECT_EQ(ra[r].generations[g].best, rb[r].generations[g].best);
          EXPECT_EQ(ra[r].generations[g].mean, rb[r].generations[g].mean);
          EXPECT_EQ(ra[r].generations[g].steps, rb[r].generations[g].steps);
        }
      }
    }
  }
}

TEST(Campaign, RunsDifferAndListenerSeesEverything) {
  const ExperimentSpec spec = testing::small_experiment();
  Recorder rec;
  const CampaignResult res = run_campaign(spec, {2}, rec);
  EXPECT_EQ(rec.generations, spec.runs * spec.generations);
  EXPECT_EQ(rec.runs, spec.runs);
  const auto& runs = res.controllers.front().runs;
  ASSERT_EQ(runs.size(), 2U);
  EXPECT_NE(runs[0].seed, runs[1].seed);
  EXPECT_NE(runs[0].best_fitness, runs[1].best_fitness);
  EXPECT_EQ(runs[0].best_genome.size(), spec.controllers.front().genome_size());
}

TEST(Campaign, MeanFitnessImproves) {
  ExperimentSpec spec = testing::small_experiment();
  spec.generations = 10;
  spec.runs = 2;
  const auto [first, last] = testing::first_and_last_mean(run_with_threads(spec, 2));
  EXPECT_GT(last, first * 1.2) << "mean fitness " << first << " -> " << last;
}

// What `esc replay --evaluations` builds on: one run made alone is the run made in the whole
// campaign, and the candidates' outcomes are what each generation's statistics summarise.
TEST(Campaign, OneRunMadeAloneIsTheRunOfTheWholeCampaignCandidateByCandidate) {
  const ExperimentSpec spec = testing::small_experiment();
  const CampaignResult whole = run_with_threads(spec, 2);
  struct Outcomes final : CampaignListener {
    std::vector<std::vector<evo::Outcome>> generations;
    void candidates_evaluated(const control::ControllerSpec&, int run, int generation,
                              std::span<const evo::Outcome> outcomes) override {
      EXPECT_EQ(run, 1);
      EXPECT_EQ(generation, static_cast<int>(generations.size()));
      generations.emplace_back(outcomes.begin(), outcomes.end());
    }
  } seen;
  CampaignOptions options{2};
  options.only_runs = {1};
  const CampaignResult alone = run_campaign(spec, options, seen);
  const RunResult& a = alone.controllers.front().runs[1];
  const RunResult& w = whole.controllers.front().runs[1];
  EXPECT_TRUE(alone.controllers.front().runs[0].generations.empty()) << "run 0 was not asked for";
  EXPECT_EQ(a.best_genome, w.best_genome);
  ASSERT_EQ(a.generations.size(), w.generations.size());
  ASSERT_EQ(seen.generations.size(), w.generations.size());
  for (std::size_t g = 0; g < w.generations.size(); ++g) {
    EXPECT_EQ(a.generations[g].best, w.generations[g].best);
    EXPECT_EQ(a.generations[g].mean, w.generations[g].mean);
    ASSERT_EQ(seen.generations[g].size(), static_cast<std::size_t>(w.generations[g].evaluations));
    double best = -1e300;
    for (const evo::Outcome& o : seen.generations[g]) best = std::max(best, o.objectives.front());
    EXPECT_EQ(best, w.generations[g].best) << g;
  }
}

}  // namespace
}  // namespace esc::eval
