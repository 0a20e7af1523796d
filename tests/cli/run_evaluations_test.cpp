// `esc replay DIR --evaluations`: a stored run made again from its seed gives every
// evaluation it made, checked against what the run stored (each generation's best, the
// MAP-Elites archive's descriptors), and draws where they fall over the maze.
#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/cli/esc_process.hpp"
#include "tests/cli/results_support.hpp"

namespace {

using namespace cli_test;

std::size_t column(const std::vector<std::string>& header, const std::string& name) {
  return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
}

class RunEvaluations : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new fs::path(scratch("run-evaluations"));
    const std::string mazes = std::string(ESC_SOURCE_DIR) + "/experiments/lehman_stanley/mazes.esc";
    ASSERT_EQ(esc("run " + mazes + " --runs 2 --generations 3 --set steps=40 --out " + dir_->string()).status, 0);
  }
  static void TearDownTestSuite() { delete dir_; }
  static fs::path* dir_;
};

fs::path* RunEvaluations::dir_ = nullptr;

TEST_F(RunEvaluations, EveryEvaluationOfARunComesBackAsTheRunMadeIt) {
  const fs::path out = scratch("run-evaluations-out");
  const Outcome o = esc("replay " + (*dir_ / "fitness_based").string() + " --run 2 --evaluations --arena --threads 2 "
                        "--out " + out.string());
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_NE(o.output.find("identical to the stored run in every generation: 750 evaluations"), std::string::npos)
      << o.output;
  const auto rows = csv_rows(slurp(out / "evaluations-navigator_net-run-02.csv"));
  ASSERT_EQ(rows.size(), 751u);
  const std::vector<std::string>& header = rows.front();
  EXPECT_EQ(header, (std::vector<std::string>{"generation", "candidate", "reach_goal", "final_x", "final_y"}));
  // Each generation's best is the one the run stored (CMA-ES maximises the fitness).
  std::map<std::string, double> best;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const double v = std::stod(rows[i][2]);
    const auto [it, first] = best.try_emplace(rows[i][0], v);
    if (!first) it->second = std::max(it->second, v);
    EXPECT_EQ(rows[i][1], std::to_string((i - 1) % 250));
  }
  const auto stored = csv_rows(esc("export " + dir_->string() + " --format csv").output);
  std::size_t compared = 0;
  for (std::size_t i = 1; i < stored.size(); ++i)
    if (stored[i][column(stored[0], "condition")] == "fitness_based" && stored[i][column(stored[0], "run")] == "2") {
      EXPECT_EQ(best.at(stored[i][column(stored[0], "generation")]), std::stod(stored[i][column(stored[0], "best")]));
      ++compared;
    }
  EXPECT_EQ(compared, 3u);
  // Where they ended, over the maze: its walls, its goal, the count.
  const std::string svg = slurp(out / "evaluations-navigator_net-run-02.svg");
  EXPECT_NE(svg.find("condition fitness_based of study medium_maze_methods"), std::string::npos);
  EXPECT_NE(svg.find("<polygon"), std::string::npos);
  EXPECT_NE(svg.find("#d62728"), std::string::npos) << "the goal";
  EXPECT_NE(svg.find("750 evaluations"), std::string::npos);
}

TEST_F(RunEvaluations, MapElitesElitesAreAmongTheEvaluationsMadeAgain) {
  const fs::path out = scratch("run-evaluations-elites");
  const Outcome o = esc("replay " + (*dir_ / "map_elites").string() + " --run 1 --evaluations --out " + out.string());
  ASSERT_EQ(o.status, 0) << o.output;
  std::set<std::pair<std::string, std::string>> ends;
  for (const auto& r : csv_rows(slurp(out / "evaluations-navigator_net-run-01.csv"))) ends.emplace(r[3], r[4]);
  const auto archive = csv_rows(esc("export " + dir_->string() + " --table archive").output);
  ASSERT_GT(archive.size(), 1u);
  const std::size_t x = column(archive[0], "final_x"), y = column(archive[0], "final_y");
  std::size_t elites = 0;
  for (std::size_t i = 1; i < archive.size(); ++i)
    if (archive[i][column(archive[0], "condition")] == "map_elites" && archive[i][column(archive[0], "run")] == "1") {
      EXPECT_TRUE(ends.contains({archive[i][x], archive[i][y]})) << archive[i][x] << ", " << archive[i][y];
      ++elites;
    }
  EXPECT_GT(elites, 10u);
  // No --arena: the descriptors' plane alone.
  EXPECT_EQ(slurp(out / "evaluations-navigator_net-run-01.svg").find("<polygon"), std::string::npos);
}

TEST_F(RunEvaluations, WhatCannotBeMadeAgainIsRefused) {
  const std::string condition = (*dir_ / "novelty").string();
  Outcome o = esc("replay " + condition + " --arena");
  EXPECT_EQ(o.status, 2);
  EXPECT_NE(o.output.find("esc: error: --arena draws a run's evaluations (--evaluations)"), std::string::npos)
      << o.output;
  o = esc("replay " + condition + " --evaluations --member 3");
  EXPECT_EQ(o.status, 2);
  EXPECT_NE(o.output.find("--evaluations makes a stored run again as it ran"), std::string::npos) << o.output;
  o = esc("replay " + condition + " --evaluations --run 3");
  EXPECT_EQ(o.status, 1);
  EXPECT_NE(o.output.find("has no finished run 3"), std::string::npos) << o.output;
}

}  // namespace
