#pragma once
// What the campaign tests check: two campaigns gave the same results bit for bit, and a
// listener that keeps the state of every run after one generation (to resume from) and
// every best evaluation replayed.
#include <gtest/gtest.h>

#include <initializer_list>
#include <utility>
#include <vector>

#include "runtime/eval/campaign.hpp"

namespace esc::testing {

// Keeps the state after generation `at` of every run, and every traced best evaluation.
struct Snapshotter final : eval::CampaignListener {
  int at = 0;
  std::vector<eval::ResumePoint::InProgress> states;
  std::vector<std::pair<eval::RunResult, std::vector<eval::TraceStep>>> traces;
  void checkpoint(const control::ControllerSpec& c, const eval::RunState& s) override {
    if (static_cast<int>(s.generations.size()) == at + 1) states.push_back({c.name, s});
  }
  void best_traced(const control::ControllerSpec&, const eval::RunResult& r,
                   std::span<const eval::TraceStep> t) override {
    traces.emplace_back(r, std::vector<eval::TraceStep>(t.begin(), t.end()));
  }
};

// The first controller's population mean fitness at the first and the last generation, summed
// over its runs.
inline std::pair<double, double> first_and_last_mean(const eval::CampaignResult& res) {
  double first = 0.0;
  double last = 0.0;
  for (const auto& r : res.controllers.front().runs) {
    first += r.generations.front().mean;
    last += r.generations.back().mean;
  }
  return {first, last};
}

inline void expect_same(const eval::CampaignResult& a, const eval::CampaignResult& b) {
  ASSERT_EQ(a.controllers.size(), b.controllers.size());
  for (std::size_t c = 0; c < a.controllers.size(); ++c) {
    ASSERT_EQ(a.controllers[c].runs.size(), b.controllers[c].runs.size());
    for (std::size_t r = 0; r < a.controllers[c].runs.size(); ++r) {
      const eval::RunResult& x = a.controllers[c].runs[r];
      const eval::RunResult& y = b.controllers[c].runs[r];
      EXPECT_EQ(x.best_fitness, y.best_fitness);
      EXPECT_EQ(x.best_genome, y.best_genome);
      EXPECT_EQ(x.best_tree, y.best_tree);
      EXPECT_EQ(x.best_behavior, y.best_behavior);
      EXPECT_EQ(x.best_generation, y.best_generation);
      EXPECT_EQ(x.best_index, y.best_index);
      EXPECT_EQ(x.action_usage, y.action_usage);
      EXPECT_EQ(x.success_evaluation, y.success_evaluation);
      ASSERT_EQ(x.generations.size(), y.generations.size());
      for (std::size_t g = 0; g < x.generations.size(); ++g) {
        EXPECT_EQ(x.generations[g].best, y.generations[g].best);
        EXPECT_EQ(x.generations[g].mean, y.generations[g].mean);
        EXPECT_EQ(x.generations[g].sd, y.generations[g].sd);
        EXPECT_EQ(x.generations[g].steps, y.generations[g].steps);
      }
    }
  }
}

// `spec` resumed after each of `generations` (its first run finished, taken from `whole`, its
// second in progress from a state kept after that generation) gives `whole` bit for bit.
inline void expect_resumes_to(const eval::ExperimentSpec& spec, const eval::CampaignResult& whole,
                              std::initializer_list<int> generations) {
  for (const int at : generations) {
    Snapshotter snap;
    snap.at = at;
    (void)eval::run_campaign(spec, {1}, snap);
    ASSERT_EQ(snap.states.size(), static_cast<std::size_t>(spec.runs));
    eval::ResumePoint point;
    point.finished.push_back({spec.controllers[0].name, whole.controllers[0].runs[0]});
    point.in_progress.push_back(snap.states[1]);
    eval::CampaignListener quiet;
    expect_same(whole, eval::run_campaign(spec, {2, &point}, quiet));
  }
}

}  // namespace esc::testing
