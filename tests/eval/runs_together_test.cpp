// Runs that advance together (CampaignOptions::runs_at_once, and the automatic choice):
// pooling several runs' generations changes who evaluates what and the order the listener
// hears of runs, never a result; a campaign stopped with several runs in progress resumes
// bit for bit however many runs advance together afterwards.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <utility>

#include "runtime/eval/campaign.hpp"
#include "tests/eval/campaign_checks.hpp"
#include "tests/eval/gp_experiment.hpp"
#include "tests/eval/test_experiment.hpp"
#include "tests/algorithm_settings.hpp"

namespace esc::eval {
namespace {

using testing::expect_same;
using testing::Snapshotter;

// Networks by the ES (6 generations) and trees by GP (2), 3 runs each: runs of different
// lengths and algorithms share rounds.
ExperimentSpec mixed_experiment() {
  ExperimentSpec mixed = testing::gp_experiment();
  mixed.controllers.insert(mixed.controllers.begin(), testing::small_experiment().controllers.front());
  gp_of(mixed).generations = 2;
  mixed.runs = 3;
  return mixed;
}

CampaignOptions together(int threads, int runs_at_once) {
  CampaignOptions o;
  o.threads = threads;
  o.runs_at_once = runs_at_once;
  return o;
}

// Checks each run's events: generations in order, checkpoints after them, run_done last.
struct EventOrder final : CampaignListener {
  std::map<std::pair<std::string, int>, int> generations;
  std::map<std::pair<std::string, int>, bool> closed;
  int most_open = 0;   // runs started and not yet closed, at most
  int interleavings = 0;
  std::pair<std::string, int> last{};
  void generation_done(const control::ControllerSpec& c, int run, const GenerationStats& g) override {
    const auto key = std::make_pair(c.name, run);
    EXPECT_FALSE(closed[key]) << c.name << " run " << run;
    EXPECT_EQ(g.generation, generations[key]++) << c.name << " run " << run;
    if (!last.first.empty() && last != key) ++interleavings;
    last = key;
    int open = 0;
    for (const auto& [k, n] : generations) open += closed[k] ? 0 : 1;
    most_open = std::max(most_open, open);
  }
  void run_done(const control::ControllerSpec& c, const RunResult& r) override {
    const auto key = std::make_pair(c.name, r.run);
    EXPECT_EQ(generations[key], static_cast<int>(r.generations.size()));
    closed[key] = true;
  }
};

TEST(RunsTogether, ResultsDoNotDependOnHowManyRunsAdvanceTogether) {
  const ExperimentSpec spec = mixed_experiment();
  CampaignListener quiet;
  const CampaignResult alone = run_campaign(spec, together(1, 1), quiet);
  expect_same(alone, run_campaign(spec, together(2, 2), quiet));
  expect_same(alone, run_campaign(spec, together(3, 4), quiet));
  expect_same(alone, run_campaign(spec, together(2, 100), quiet));
  expect_same(alone, run_campaign(spec, together(2, 0), quiet));
}

TEST(RunsTogether, EachRunsEventsComeInOrder) {
  const ExperimentSpec spec = mixed_experiment();
  EventOrder one_at_a_time;
  (void)run_campaign(spec, together(2, 1), one_at_a_time);
  EXPECT_EQ(one_at_a_time.most_open, 1);
  EXPECT_EQ(one_at_a_time.interleavings, 3 * 3 - 1);   // 9 runs, one after the other
  EventOrder four;
  (void)run_campaign(spec, together(2, 4), four);
  EXPECT_EQ(four.most_open, 4);
  EXPECT_GT(four.interleavings, 9);
  EXPECT_EQ(four.closed.size(), 9u);
}

TEST(RunsTogether, TheAutomaticChoiceFillsTheWorkers) {
  // 20 offspring per generation: with 1 thread, 16 evaluations per worker make runs go one
  // at a time only when a generation has at least 16 evaluations; lambda 4 lets all 3 go.
  ExperimentSpec spec = testing::small_experiment();
  spec.runs = 3;
  EventOrder big;
  (void)run_campaign(spec, together(1, 0), big);
  EXPECT_EQ(big.most_open, 1);
  es_of(spec).mu = 2;
  es_of(spec).lambda = 4;
  EventOrder small;
  (void)run_campaign(spec, together(1, 0), small);
  EXPECT_EQ(small.most_open, 3);
}

TEST(RunsTogether, StoppedWithSeveralRunsInProgressResumesBitIdentical) {
  const ExperimentSpec spec = mixed_experiment();
  CampaignListener quiet;
  const CampaignResult whole = run_campaign(spec, together(2, 1), quiet);
  Snapshotter snap;
  snap.at = 1;
  (void)run_campaign(spec, together(1, 6), snap);
  // Every run's state after generation 1: the networks' runs are in progress, the trees'
  // (2 generations) done but not closed.
  ASSERT_EQ(snap.states.size(), 9u);
  ResumePoint point;
  for (const auto& s : snap.states) point.in_progress.push_back(s);
  for (const int runs_at_once : {1, 3}) {
    CampaignOptions o = together(2, runs_at_once);
    o.resume = &point;
    expect_same(whole, run_campaign(spec, o, quiet));
  }
}

}  // namespace
}  // namespace esc::eval
