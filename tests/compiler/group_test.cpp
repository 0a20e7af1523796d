// Groups in the language (docs/groups.md): `robot NAME x N`, `--set robots=N`, what a group
// cannot do yet, and what an evaluation of a group measures.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "runtime/eval/evaluator.hpp"
#include "tests/compiler/helpers.hpp"

namespace esc::compiler::test {
namespace {

std::string script(const std::string& robot_item, const std::string& fitness_body = "step: forward_speed",
                   const std::string& more = "") {
  return "robot bot { inertia on }\n"
         "arena a { size 1m x 1m  start random }\n"
         "fitness f { " + fitness_body + " }\n"
         "controller c = mlp(ir[0..7] -> wheels)\n"
         "experiment e { arena a  fitness f  epochs 2 x 30 steps  compare c  " + robot_item + "\n" + more + "}\n";
}

eval::Evaluation evaluate(const eval::ExperimentSpec& x, double weight = 0.3) {
  eval::Evaluator ev(x);
  const control::ControllerSpec& c = x.controllers.front();
  return ev.evaluate(c, std::vector<double>(c.genome_size(), weight), 11);
}

TEST(Groups, ARobotItemTakesACount) {
  EXPECT_EQ(first_experiment(script("robot bot x 4"), "g.esc").robots, 4);
  EXPECT_EQ(first_experiment(script("robot bot { inertia off } x 2"), "g.esc").robots, 2);
  const eval::ExperimentSpec alone = first_experiment(script("robot bot"), "g.esc");
  EXPECT_EQ(alone.robots, 1);
  // Resolved only for a group: a robot alone resolves as it always did.
  EXPECT_FALSE(alone.resolved_settings.contains("robots"));
  EXPECT_EQ(first_experiment(script("robot bot x 3"), "g.esc").resolved_settings.at("robots"), "3");
  // And `--set robots=N`.
  eval::ExperimentSpec x = alone;
  EXPECT_EQ(apply_setting(x, "robots", "6"), "");
  EXPECT_EQ(x.robots, 6);
}

TEST(Groups, ACountOutOfRangeIsALocatedError) {
  for (const char* count : {"0", "257"}) {
    const std::string out = refusal(script(std::string("robot bot x ") + count), "g.esc");
    EXPECT_NE(out.find("g.esc:5:"), std::string::npos) << out;
    EXPECT_NE(out.find("robots"), std::string::npos) << out;
  }
  eval::ExperimentSpec x = first_experiment(script("robot bot"), "g.esc");
  EXPECT_NE(apply_setting(x, "robots", "0"), "");
  EXPECT_EQ(x.robots, 1) << "left unchanged on error";
}

TEST(Groups, StepsFoldedIntoAnEndTermAreRefusedForAGroup) {
  const std::string folded = "step: 0  epoch: mean(forward_speed)";
  const std::string out = refusal(script("robot bot x 3", folded), "g.esc");
  EXPECT_NE(out.find("folds its steps"), std::string::npos) << out;
  EXPECT_NE(out.find("g.esc:5:"), std::string::npos) << out;
  // Alone it compiles; `--set robots=3` is then refused the same way.
  eval::ExperimentSpec x = first_experiment(script("robot bot", folded), "g.esc");
  const std::string error = apply_setting(x, "robots", "3");
  EXPECT_NE(error.find("folds its steps"), std::string::npos) << error;
}

TEST(Groups, EveryTermIsTheMeanOverTheRobots) {
  // `robots` is the group's size in every robot's frame; the end term counts it once an epoch.
  const eval::ExperimentSpec x = first_experiment(script("robot bot x 3", "step: 0  epoch: robots"), "g.esc");
  EXPECT_EQ(evaluate(x).fitness, 2 * 3.0);
  // The centroid's distances average to at most the spread, which is at most half the diagonal
  // of where the robots can be, and at least 0; with one robot both are 0.
  const eval::ExperimentSpec spread = first_experiment(script("robot bot x 5", "step: 0  epoch: spread"), "g.esc");
  const eval::ExperimentSpec mean = first_experiment(script("robot bot x 5", "step: 0  epoch: centroid_distance"), "g.esc");
  const double s = evaluate(spread).fitness, m = evaluate(mean).fitness;
  EXPECT_GT(m, 0.0);
  EXPECT_LE(m, s);
  EXPECT_LT(s, 2 * std::sqrt(2.0) / 2);
  const eval::ExperimentSpec alone = first_experiment(script("robot bot", "step: 0  epoch: spread + centroid_distance"), "g.esc");
  EXPECT_EQ(evaluate(alone).fitness, 0.0);
}

TEST(Groups, AGroupOfOneIsTheRobotAlone) {
  const eval::ExperimentSpec alone = first_experiment(script("robot bot"), "g.esc");
  eval::ExperimentSpec one = first_experiment(script("robot bot x 2"), "g.esc");
  ASSERT_EQ(apply_setting(one, "robots", "1"), "");
  const eval::Evaluation a = evaluate(alone), b = evaluate(one);
  EXPECT_EQ(a.fitness, b.fitness);
  EXPECT_EQ(a.steps, b.steps);
  // Two robots are not one.
  EXPECT_NE(evaluate(first_experiment(script("robot bot x 2"), "g.esc")).fitness, a.fitness);
}

TEST(Groups, AnEpochStopsWhenAnyRobotsConditionHolds) {
  // Robot 0 starts at the fixed start, far short of the line that stops an epoch; some of the
  // five others start beyond it (seed 11): a robot other than 0 ends the group's epochs after
  // their first step, where robot 0's condition alone would let them run their 100.
  const std::string text = "robot bot { inertia on }\n"
                           "arena w { size 1m x 1m  start at (10cm, 50cm) }\n"
                           "fitness f { step: 1  stop epoch when x > 60cm }\n"
                           "controller c = mlp(ir[0..7] -> wheels)\n"
                           "experiment e { arena w  fitness f  epochs 2 x 100 steps  compare c  robot bot x 6 }\n";
  EXPECT_EQ(evaluate(first_experiment(text, "g.esc")).steps, 2);
}

TEST(Groups, ARobotAloneReadsTheGroupsObservablesToo) {
  // One robot: a group of one, its own centroid, no neighbour nearer than the diagonal.
  const eval::ExperimentSpec x =
      first_experiment(script("robot bot", "step: 0  epoch: robots + nearest_robot + 10 * spread"), "g.esc");
  EXPECT_NEAR(evaluate(x).fitness, 2 * (1 + std::sqrt(2.0)), 1e-12);
}

TEST(Groups, TheCentroidMovesFromWhereItWasAtTheEpochsStart) {
  const std::string moved = "step: 0  epoch: centroid_moved";
  const eval::ExperimentSpec x = first_experiment(script("robot bot x 3", moved), "g.esc");
  EXPECT_EQ(evaluate(x, 0.0).fitness, 0.0);   // a zero network: the wheels never turn
  EXPECT_GT(evaluate(x, 0.3).fitness, 0.01);
}

TEST(Groups, AGroupsUsageCountsAddUpToItsSteps) {
  const std::string text = "robot bot { inertia on }\n"
                           "arena a { size 1m x 1m  start random }\n"
                           "behavior go() { wheels(1, 1) }\nbehavior turn() { wheels(-1, 1) }\n"
                           "fitness f { step: forward_speed  stop epoch when collision }\n"
                           "controller sc = symbolic(mlp(ir[0..7] -> hidden 2), actions [go, turn])\n"
                           "experiment e { arena a  fitness f  epochs 2 x 50 steps  compare sc  robot bot x 3 }\n";
  const eval::ExperimentSpec x = first_experiment(text, "g.esc");
  const eval::Evaluation e = evaluate(x);
  ASSERT_EQ(e.usage.size(), 2U);
  EXPECT_EQ(e.usage[0] + e.usage[1], e.steps);
}

TEST(Groups, AGroupMustFitTheArenasFloor) {
  // 104 Kheperas-sized discs (with the starts' 5 mm) cover 54% of an 80 cm arena.
  const std::string text = "robot bot { inertia on }\n"
                           "arena a { size 80cm x 80cm }\n"
                           "fitness f { step: forward_speed }\n"
                           "controller c = mlp(ir[0..7] -> wheels)\n"
                           "experiment e { arena a  fitness f  compare c  robot bot x 104 }\n";
  const std::string out = refusal(text, "g.esc");
  EXPECT_NE(out.find("g.esc:5:"), std::string::npos) << out;
  EXPECT_NE(out.find("104 robots"), std::string::npos) << out;
  EXPECT_NE(out.find("54%"), std::string::npos) << out;
}

}  // namespace
}  // namespace esc::compiler::test
