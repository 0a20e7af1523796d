// Groups in the language (docs/groups.md): `robot NAME x N`, `--set robots=N`, what a group
// cannot do yet, and what an evaluation of a group measures.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
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

// A term that folds the steps (`mean(...)` over the steps) folds each robot's own steps: the
// group's is the robots' reduced. `mean(robots)` is the group's size whatever the steps;
// `max(nearest_robot)` of a robot is at least its nearest robot at the epoch's end.
TEST(Groups, StepsFoldedIntoAnEndTermAreEachRobots) {
  EXPECT_EQ(evaluate(first_experiment(script("robot bot x 3", "step: 0  epoch: mean(robots)"), "g.esc")).fitness, 2 * 3.0);
  const double folded = evaluate(first_experiment(script("robot bot x 3", "step: 0  epoch: max(nearest_robot)"), "g.esc")).fitness;
  const double last = evaluate(first_experiment(script("robot bot x 3", "step: 0  epoch: nearest_robot"), "g.esc")).fitness;
  EXPECT_GE(folded, last);
  EXPECT_GT(folded, 0.0);
  // The worst robot's mean forward speed, and the best one's.
  const double low = evaluate(first_experiment(script("robot bot x 3", "step: 0  epoch: mean(forward_speed)  over robots min"), "g.esc")).fitness;
  const double high = evaluate(first_experiment(script("robot bot x 3", "step: 0  epoch: mean(forward_speed)  over robots max"), "g.esc")).fitness;
  EXPECT_LE(low, high);
  // `--set robots=3` on a robot alone's folding experiment is a group's as well.
  eval::ExperimentSpec x = first_experiment(script("robot bot", "step: 0  epoch: mean(robots)"), "g.esc");
  EXPECT_EQ(apply_setting(x, "robots", "3"), "");
  EXPECT_EQ(evaluate(x).fitness, 2 * 3.0);
}

// `over robots sum|min|max` reduces every term of the fitness over the robots as it says: the
// spread is the largest centroid distance, so `max` of centroid_distance is it, and the mean
// lies between min and max; `sum` is the mean times the robots.
TEST(Groups, OverRobotsReducesEveryTermAsItSays) {
  const auto fitness = [](const std::string& over, const std::string& term = "centroid_distance") {
    const std::string body = "step: " + term + "  epoch: " + term + (over.empty() ? "" : "  over robots " + over);
    return evaluate(first_experiment(script("robot bot x 4", body), "g.esc")).fitness;
  };
  const double mean = fitness(""), sum = fitness("sum"), low = fitness("min"), high = fitness("max");
  EXPECT_EQ(fitness("mean"), mean);
  EXPECT_NEAR(sum, 4 * mean, 1e-9);
  EXPECT_LT(low, mean);
  EXPECT_GT(high, mean);
  EXPECT_NEAR(high, fitness("", "spread"), 1e-9);
  const eval::ExperimentSpec x = first_experiment(script("robot bot x 4", "step: 0  over robots: min"), "g.esc");
  EXPECT_EQ(x.fitness.over_robots, eval::Reduction::Min);
  EXPECT_EQ(x.resolved_settings.at("fitness.over_robots"), "min");
  // A descriptor's too: `over robots max` of the centroid distance is the spread.
  const eval::ExperimentSpec d = first_experiment(
      script("robot bot x 4", "step: 0",
             "descriptor far: centroid_distance in [0, 1] over robots max  descriptor spread: spread in [0, 1]"),
      "g.esc");
  EXPECT_EQ(d.descriptors[0].over_robots, eval::Reduction::Max);
  const eval::Evaluation e = evaluate(d);
  EXPECT_NEAR(e.descriptors[0], e.descriptors[1], 1e-12);
  EXPECT_NE(d.resolved_settings.at("descriptors").find("over robots max"), std::string::npos);
  // A robot alone's terms are its own whatever the reduction, and resolve as they always did.
  const eval::ExperimentSpec alone = first_experiment(script("robot bot", "step: forward_speed  over robots sum"), "g.esc");
  EXPECT_EQ(evaluate(alone).fitness, evaluate(first_experiment(script("robot bot"), "g.esc")).fitness);
  EXPECT_FALSE(first_experiment(script("robot bot"), "g.esc").resolved_settings.contains("fitness.over_robots"));
}

TEST(Groups, OverSomethingElseOrAnUnknownReductionIsALocatedError) {
  std::string out = refusal(script("robot bot x 2", "step: 0  over robots median"), "g.esc");
  EXPECT_NE(out.find("g.esc:3:"), std::string::npos) << out;
  EXPECT_NE(out.find("`median` is not a reduction over the robots"), std::string::npos) << out;
  out = refusal(script("robot bot x 2", "step: 0  over epochs max"), "g.esc");
  EXPECT_NE(out.find("not over `epochs`"), std::string::npos) << out;
  EXPECT_NE(out.find("over robots max"), std::string::npos) << out;
  out = refusal(script("robot bot x 2", "step: 0  over robots max  over robots min"), "g.esc");
  EXPECT_NE(out.find("the reduction over the robots is already given"), std::string::npos) << out;
  out = refusal(script("robot bot x 2", "step: 0  over robots mex"), "g.esc");
  EXPECT_NE(out.find("did you mean `max`?"), std::string::npos) << out;
}

// `clusters(R)`, `largest_cluster(R)`, `cluster_size(R)`: each radius the experiment reads
// gets its slots, in the order first read, the same radius the same slots.
TEST(Groups, ClustersAreCountedWithinEachRadiusTheExperimentReads) {
  const eval::ExperimentSpec x = first_experiment(
      script("robot bot x 4", "step: 0  epoch: clusters(15cm) + largest_cluster(0.15m) - cluster_size(30cm)"), "g.esc");
  EXPECT_EQ(x.cluster_radii, (std::vector<double>{0.15, 0.3}));
  const std::vector<expr::Instr> code(x.fitness.epoch_end->code().begin(), x.fitness.epoch_end->code().end());
  std::vector<expr::Slot> loads;
  for (const expr::Instr& in : code)
    if (in.op == expr::Op::Load) loads.push_back(in.slot);
  EXPECT_EQ(loads, (std::vector<expr::Slot>{expr::slot::clusters, expr::slot::largest_cluster, expr::slot::cluster_size + 1}));
  // Four robots make between one and four clusters, of one to four robots, each epoch.
  const double f = evaluate(first_experiment(script("robot bot x 4", "step: 0  epoch: clusters(20cm)"), "g.esc")).fitness;
  EXPECT_GE(f, 2 * 1.0);
  EXPECT_LE(f, 2 * 4.0);
  // Alone: one cluster of one.
  EXPECT_EQ(evaluate(first_experiment(script("robot bot", "step: 0  epoch: clusters(20cm) * cluster_size(1cm)"), "g.esc"))
                .fitness,
            2 * 1.0);
  // A descriptor reads them too, from the same slots.
  const eval::ExperimentSpec d = first_experiment(
      script("robot bot x 3", "step: clusters(10cm)", "descriptor apart: largest_cluster(10cm) in [1, 3]"), "g.esc");
  EXPECT_EQ(d.cluster_radii, (std::vector<double>{0.1}));
}

TEST(Groups, AClusterRadiusIsAPositiveLengthAndAtMostFourAreRead) {
  for (const char* bad : {"clusters(15)", "clusters(0cm)", "clusters(1s)", "clusters(speed)", "clusters()"}) {
    const std::string out = refusal(script("robot bot x 3", std::string("step: ") + bad), "g.esc");
    EXPECT_NE(out.find("takes a radius, a positive length with its unit"), std::string::npos) << bad << out;
    EXPECT_NE(out.find("g.esc:3:"), std::string::npos) << out;
  }
  const std::string five =
      refusal(script("robot bot x 3", "step: clusters(1cm) + clusters(2cm) + clusters(3cm) + clusters(4cm) + clusters(5cm)"),
              "g.esc");
  EXPECT_NE(five.find("at most 4 radii"), std::string::npos) << five;
  const std::string behavior = refusal("behavior b() { wheels(clusters(10cm), 0) }\n" + script("robot bot x 2"), "g.esc");
  EXPECT_NE(behavior.find("not by a behavior"), std::string::npos) << behavior;
}

// `formation line 10cm`, `formation circle 15cm`, `formation at [...]`: read into the
// experiment, resolved only when given, settable with `--set`, and checked against the group
// and the arena with located errors.
TEST(Groups, AFormationIsDeclaredSetAndChecked) {
  const eval::ExperimentSpec line = first_experiment(script("robot bot x 3  formation line 10cm"), "g.esc");
  EXPECT_EQ(line.formation.kind, sim::FormationKind::Line);
  EXPECT_DOUBLE_EQ(line.formation.spacing_m, 0.1);
  EXPECT_EQ(line.resolved_settings.at("formation"), "line");
  EXPECT_EQ(line.resolved_settings.at("formation_spacing"), "0.1 m");
  const eval::ExperimentSpec at =
      first_experiment(script("robot bot x 2  formation at [(20cm, 20cm, 90deg), (40cm, 20cm, 0deg)]"), "g.esc");
  ASSERT_EQ(at.formation.at.size(), 2U);
  EXPECT_DOUBLE_EQ(at.formation.at[1].x_m, 0.4);
  EXPECT_NEAR(at.formation.at[0].heading_rad, std::numbers::pi / 2, 1e-15);
  // Random resolves as it always did; `--set` changes it as it changes any setting.
  eval::ExperimentSpec x = first_experiment(script("robot bot x 3"), "g.esc");
  EXPECT_FALSE(x.resolved_settings.contains("formation"));
  EXPECT_NE(apply_setting(x, "formation", "circle").find("spacing must be a length greater than 0"), std::string::npos);
  EXPECT_EQ(x.formation.kind, sim::FormationKind::Random) << "unchanged on error";
  EXPECT_EQ(apply_settings(x, {{"formation", "circle"}, {"formation_spacing", "12cm"}}), "");
  EXPECT_EQ(x.formation.kind, sim::FormationKind::Circle);
  EXPECT_EQ(x.resolved_settings.at("formation_spacing"), "0.12 m");
  // Evaluated as a circle: every robot starts 12 cm from the others' centroid.
  const eval::ExperimentSpec circle =
      first_experiment(script("robot bot x 3  formation circle 12cm", "step: 0  epoch: centroid_distance  stop epoch when step >= 0"),
                       "g.esc");
  EXPECT_NEAR(evaluate(circle).fitness, 2 * 0.12, 0.01);
}

TEST(Groups, AFormationTheGroupCannotTakeIsALocatedError) {
  std::string out = refusal(script("robot bot x 3  formation line"), "g.esc");
  EXPECT_NE(out.find("`formation line` takes a length"), std::string::npos) << out;
  EXPECT_NE(out.find("g.esc:5:"), std::string::npos) << out;
  out = refusal(script("robot bot x 3  formation zigzag 10cm"), "g.esc");
  EXPECT_NE(out.find("zigzag"), std::string::npos) << out;
  out = refusal(script("robot bot x 3  formation line 4cm"), "g.esc");
  EXPECT_NE(out.find("would overlap"), std::string::npos) << out;
  out = refusal(script("robot bot x 3  formation circle 60cm"), "g.esc");
  EXPECT_NE(out.find("across and the arena"), std::string::npos) << out;
  out = refusal(script("robot bot x 3  formation at [(20cm, 20cm, 0deg), (40cm, 20cm, 0deg)]"), "g.esc");
  EXPECT_NE(out.find("2 poses for 3 robots"), std::string::npos) << out;
  out = refusal(script("robot bot x 2  formation at [(20cm, 20cm), (40cm, 20cm)]"), "g.esc");
  EXPECT_NE(out.find("formation_at"), std::string::npos) << out;
  // `--set robots=3` after two poses is refused the same way.
  eval::ExperimentSpec x =
      first_experiment(script("robot bot x 2  formation at [(20cm, 20cm, 0deg), (40cm, 20cm, 0deg)]"), "g.esc");
  EXPECT_NE(apply_setting(x, "robots", "3").find("2 poses for 3 robots"), std::string::npos);
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

// `roles N`: N networks in one genome, robot i driven by role i mod N; resolved only when
// several, settable with `--set`, at most the group's robots, networks of fixed topology only.
TEST(Groups, RolesAreDeclaredSetAndChecked) {
  const eval::ExperimentSpec x = first_experiment(script("robot bot x 4  roles 2"), "g.esc");
  const control::ControllerSpec& c = x.controllers.front();
  EXPECT_EQ(x.roles, 2);
  EXPECT_EQ(x.genome_length(c), 2 * c.genome_size());
  EXPECT_EQ(x.resolved_settings.at("roles"), "2");
  eval::ExperimentSpec clonal = first_experiment(script("robot bot x 4"), "g.esc");
  EXPECT_EQ(clonal.roles, 1);
  EXPECT_FALSE(clonal.resolved_settings.contains("roles"));
  EXPECT_EQ(apply_setting(clonal, "roles", "4"), "");
  EXPECT_EQ(clonal.genome_length(c), 4 * c.genome_size());
  EXPECT_NE(apply_setting(clonal, "roles", "5").find("5 roles need at least 5 robots, and the group has 4"),
            std::string::npos);
  EXPECT_NE(apply_setting(clonal, "robots", "3").find("4 roles need at least 4 robots"), std::string::npos);
  // `roles` is still a name elsewhere.
  std::string named = script("robot bot x 2  roles 2");
  for (std::size_t at; (at = named.find("arena a")) != std::string::npos;) named.replace(at, 7, "arena roles");
  EXPECT_EQ(first_experiment(named, "g.esc").roles, 2);
}

TEST(Groups, RolesTheGroupOrTheControllersCannotHaveAreLocatedErrors) {
  std::string out = refusal(script("robot bot x 3", "step: forward_speed", "  roles 4"), "g.esc");
  EXPECT_NE(out.find("g.esc:6:3: error: 4 roles need at least 4 robots, and the group has 3"), std::string::npos) << out;
  out = refusal(script("robot bot x 3", "step: forward_speed", "  roles 0"), "g.esc");
  EXPECT_NE(out.find("g.esc:6:"), std::string::npos) << out;
  const std::string trees = "robot bot { inertia on }\n"
                            "arena a { size 1m x 1m  start random }\n"
                            "fitness f { step: forward_speed }\n"
                            "primitives p { functions + - terminals ir[0..7] }\n"
                            "controller t = tree(wheels, primitives p)\n"
                            "experiment e { arena a  fitness f  compare t  robot bot x 2\n"
                            "  roles 2 evolve gp(population 10) }\n";
  out = refusal(trees, "g.esc");
  EXPECT_NE(out.find("g.esc:7:3: error: `t` is a tree: roles are networks of fixed topology"), std::string::npos) << out;
}

// `robot bot x 2, lit x 3`: a group of two bodies, in robot order, reading the same sensors;
// resolved as `bodies` and each further body's settings that differ; `--set
// robot.KEY` changes every body, `--set robots` is refused.
TEST(Groups, AGroupOfSeveralBodiesListsThemInRobotOrder) {
  const std::string lit = "robot lit = bot { emission 1  max_speed 5cm/s }\n";
  eval::ExperimentSpec x = first_experiment(lit + script("robot bot x 2, lit x 3"), "g.esc");
  EXPECT_EQ(x.robots, 5);
  ASSERT_EQ(x.bodies.size(), 2U);
  const std::vector<sim::RobotParams> every = x.robot_params();
  ASSERT_EQ(every.size(), 5U);
  EXPECT_EQ(every[1].emission.intensity, 0.0);
  EXPECT_EQ(every[2].emission.intensity, 1.0);
  EXPECT_DOUBLE_EQ(every[4].motor.max_speed_mps, 0.05);
  EXPECT_EQ(x.resolved_settings.at("bodies"), "bot x 2, lit x 3");
  EXPECT_EQ(x.resolved_settings.at("body2.emission"), "1");
  EXPECT_FALSE(x.resolved_settings.contains("body2.ir_range")) << "only what differs from the first body";
  EXPECT_FALSE(first_experiment(script("robot bot x 3"), "g.esc").resolved_settings.contains("bodies"));
  EXPECT_EQ(first_experiment(lit + script("robot bot, lit"), "g.esc").robots, 2);
  EXPECT_NE(apply_setting(x, "robots", "4").find("several bodies"), std::string::npos);
  EXPECT_EQ(apply_setting(x, "robot.ir_noise", "0.1"), "");
  EXPECT_DOUBLE_EQ(x.robot_params()[4].ir.noise_sd, 0.1);
  EXPECT_DOUBLE_EQ(x.robot_params()[0].ir.noise_sd, 0.1);
  // Two bodies alike are the group of one body, to the bit.
  const std::string same = "robot twin = bot { }\n";
  EXPECT_EQ(evaluate(first_experiment(same + script("robot bot x 2, twin x 2"), "g.esc")).fitness,
            evaluate(first_experiment(script("robot bot x 4"), "g.esc")).fitness);
  // And the lit body's light reaches the others' light sensors.
  const std::string reads_light = "step: 0  epoch: light[2]";
  EXPECT_GT(evaluate(first_experiment(lit + script("robot bot x 2, lit x 2", reads_light), "g.esc")).fitness,
            evaluate(first_experiment(lit + script("robot bot x 4", reads_light), "g.esc")).fitness);
}

// `bodyN.KEY` sets one body of a group alone, `body1` the first; `robot.KEY` sets every body, and
// the two of one key together are refused, as are bodies the group lacks and a body set apart
// from what the bodies of a group share.
TEST(Groups, OneBodyOfAGroupIsSetAlone) {
  const std::string lit = "robot lit = bot { emission 1 }\n";
  const eval::ExperimentSpec group = first_experiment(lit + script("robot bot x 2, lit x 3"), "g.esc");
  eval::ExperimentSpec x = group;
  EXPECT_EQ(apply_setting(x, "body2.max_speed", "6cm/s"), "");
  EXPECT_DOUBLE_EQ(x.robot_params()[4].motor.max_speed_mps, 0.06);
  EXPECT_DOUBLE_EQ(x.robot_params()[1].motor.max_speed_mps, group.robot.motor.max_speed_mps);
  EXPECT_EQ(x.resolved_settings.at("body2.max_speed"), "0.06 m/s");
  // The first body alone: the resolved `robot.KEY` is the first body's, and the further body,
  // now apart from it, is listed.
  x = group;
  EXPECT_EQ(apply_setting(x, "body1.emission", "0.5"), "");
  EXPECT_EQ(x.robot_params()[0].emission.intensity, 0.5);
  EXPECT_EQ(x.bodies[0].params.emission.intensity, 0.5);
  EXPECT_EQ(x.robot_params()[2].emission.intensity, 1.0);
  EXPECT_EQ(x.resolved_settings.at("robot.emission"), "0.5");
  EXPECT_EQ(x.resolved_settings.at("body2.emission"), "1");
  // Set back to the first's, a body is no longer listed apart.
  EXPECT_EQ(apply_setting(x, "body2.emission", "0.5"), "");
  EXPECT_FALSE(x.resolved_settings.contains("body2.emission"));
  // Both of one key, in either order: one would override the other.
  x = group;
  std::string m;
  for (const auto& [a, b] : {std::pair{"robot.emission", "body2.emission"}, std::pair{"body2.emission", "robot.emission"}}) {
    m = apply_settings(x, {{a, "0.3"}, {b, "0.7"}});
    EXPECT_NE(m.find("sets every body of the group and"), std::string::npos) << m;
    EXPECT_EQ(x.robot_params()[0].emission.intensity, 0.0) << "nothing set";
    EXPECT_EQ(x.robot_params()[2].emission.intensity, 1.0) << "nothing set";
  }
  // A body misspelt is said as such, not as an overlap.
  m = apply_settings(x, {{"robot.emission", "1"}, {"body02.emission", "0"}});
  EXPECT_NE(m.find("without leading zeros"), std::string::npos) << m;
  EXPECT_EQ(apply_settings(x, {{"robot.emission", "0"}, {"body2.max_speed", "6cm/s"}}), "") << "other keys";
  // Bodies the group lacks, a body's number written otherwise, an unknown key.
  x = group;
  m = apply_setting(x, "body3.emission", "0");
  EXPECT_NE(m.find("`body3.emission`: the group of experiment `e` has 2 bodies (`bot`, `lit`), `body1` to `body2` "
                   "(set every body's as `robot.emission`)"),
            std::string::npos)
      << m;
  m = apply_setting(x, "body02.emission", "0");
  EXPECT_NE(m.find("`body02.emission`: a body's number is written without leading zeros (write `body2.emission`)"),
            std::string::npos)
      << m;
  m = apply_setting(x, "body2.emision", "0");
  EXPECT_NE(m.find("unknown robot setting `body2.emision`; did you mean `body2.emission`?"), std::string::npos) << m;
  m = apply_setting(x, "body0.emission", "0");
  EXPECT_NE(m.find("unknown setting `body0.emission`; did you mean `robot.emission`?"), std::string::npos) << m;
  m = apply_setting(x, "qqqqqqqq", "0");
  EXPECT_NE(m.find("and the groups "), std::string::npos) << m;
  EXPECT_NE(m.find("bodyN.* (body N of a group alone)"), std::string::npos) << m;
  eval::ExperimentSpec alone = first_experiment(script("robot bot x 3"), "g.esc");
  m = apply_setting(alone, "body2.emission", "1");
  EXPECT_NE(m.find("`body2.emission`: the robots of experiment `e` have one body"), std::string::npos) << m;
  EXPECT_EQ(apply_setting(alone, "body1.max_speed", "6cm/s"), "") << "a robot alone is its first body";
  EXPECT_DOUBLE_EQ(alone.robot.motor.max_speed_mps, 0.06);
  // What the bodies of a group share: the world's step, and the sensors one network reads.
  x = group;
  m = apply_setting(x, "body2.control_step", "200ms");
  EXPECT_NE(m.find("`lit` has another `control_step` than `bot` (0.2 s against 0.1 s): the bodies of a group share "
                   "their drive and their control step (give every body the same `control_step`: "
                   "`robot.control_step`)"),
            std::string::npos)
      << m;
  m = apply_setting(x, "body2.ir_sensors", "[(30deg, 30deg), (-30deg, -30deg)]");
  EXPECT_NE(m.find("`lit` has another number of `ir_sensors` than `bot`"), std::string::npos) << m;
  EXPECT_NE(m.find("a network per body"), std::string::npos) << m;
}

// A robot's light is for the others: alone, `emission` compiles with a warning saying so.
TEST(Groups, EmissionWithoutOtherRobotsIsAWarning) {
  const auto alone = compile_source(script("robot bot { emission 1 }"), "g.esc", options());
  ASSERT_TRUE(alone.ok()) << rendered(alone);
  EXPECT_NE(rendered(alone).find("g.esc:5:"), std::string::npos) << rendered(alone);
  EXPECT_NE(rendered(alone).find("warning: a robot alone does not read its own light"), std::string::npos)
      << rendered(alone);
  const auto group = compile_source(script("robot bot { emission 1 } x 2"), "g.esc", options());
  ASSERT_TRUE(group.ok()) << rendered(group);
  EXPECT_TRUE(group.diagnostics.empty()) << rendered(group);
}

// Bodies of other shapes join a group (each robot is stepped, sensed and drawn with its own);
// what one controller reads, the drive and the step are the group's.
TEST(Groups, BodiesOfOtherShapesJoinAGroupThatReadsTheSameSensors) {
  const std::string big = "robot big = bot { body_radius 4cm  ir_range 8cm }\n";
  eval::ExperimentSpec x = first_experiment(big + script("robot bot x 2, big"), "g.esc");
  ASSERT_EQ(x.robots, 3);
  EXPECT_DOUBLE_EQ(x.robot_params()[1].body_radius_m, 0.0275);
  EXPECT_DOUBLE_EQ(x.robot_params()[2].body_radius_m, 0.04);
  EXPECT_EQ(x.resolved_settings.at("body2.body_radius"), "0.04 m");
  EXPECT_TRUE(std::isfinite(evaluate(x).fitness));
  // The largest body decides a formation's spacing; robot i's own radius its place.
  EXPECT_NE(refusal(big + script("robot bot x 2, big  formation line 7cm"), "g.esc").find("would overlap"),
            std::string::npos);
  (void)first_experiment(big + script("robot bot x 2, big  formation line 9cm"), "g.esc");
  EXPECT_NE(refusal(big + script("robot bot, big  formation at [(20cm, 20cm, 0deg), (26cm, 20cm, 0deg)]"), "g.esc")
                .find("robots 1 and 2 would start overlapping"),
            std::string::npos);
  (void)first_experiment(big + script("robot bot, big  formation at [(20cm, 20cm, 0deg), (27.5cm, 20cm, 0deg)]"),
                         "g.esc");
  // A further body too large for the arena is named.
  const std::string huge = "robot huge = bot { body_radius 60cm  wheel_base 10cm  max_speed 1cm/s }\n";
  EXPECT_NE(refusal(huge + script("robot bot, huge"), "g.esc").find("body 2 of the group (`huge`)"), std::string::npos)
      << refusal(huge + script("robot bot, huge"), "g.esc");
}

TEST(Groups, BodiesReadingOtherSensorsOrTooManyRobotsAreLocatedErrors) {
  std::string out = refusal("robot ep { body_radius 37mm  ir_name prox }\n" + script("robot bot x 2, ep"), "g.esc");
  EXPECT_NE(out.find("g.esc:6:83: error: `ep` has another `ir_name` than `bot` (prox against ir): the bodies of a "
                     "group share the sensors one controller reads"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("help: name its sensors as `bot` does, in the group's list: `ep { ir_name ir }`"),
            std::string::npos)
      << out;
  (void)first_experiment("robot ep { body_radius 37mm  ir_name prox }\n" + script("robot bot x 2, ep { ir_name ir }"),
                         "g.esc");
  // The world's step first: no controller makes such bodies one group. Then the number of
  // sensors, which a controller per body reads apart (tests/compiler/per_body_test.cpp).
  out = refusal("robot few = bot { substeps 6  ir_sensors [(0deg, 0deg)] }\n" + script("robot bot, few"), "g.esc");
  EXPECT_NE(out.find("`few` has another `substeps` than `bot` (6 against"), std::string::npos) << out;
  out = refusal("robot few = bot { ir_sensors [(0deg, 0deg)] }\n" + script("robot bot, few"), "g.esc");
  EXPECT_NE(out.find("`few` has another number of `ir_sensors` than `bot` (1 against 8)"), std::string::npos) << out;
  EXPECT_NE(out.find("help: compare controllers with a network per body"), std::string::npos) << out;
  // A name matters only for sensors the bodies have.
  (void)first_experiment("robot g = bot { ground_name floor }\n" + script("robot bot, g"), "g.esc");
  out = refusal(script("robot bot x 200, bot x 100"), "g.esc");
  EXPECT_NE(out.find("the group's bodies add up to 300 robots, and a group holds at most 256"), std::string::npos) << out;
  out = refusal(script("robot bot x 2, bot x 0"), "g.esc");
  EXPECT_NE(out.find("g.esc:5:"), std::string::npos) << out;
  out = refusal(script("robot bot x 2, nobody"), "g.esc");
  EXPECT_NE(out.find("nobody"), std::string::npos) << out;
  // A mistake in the first body is that mistake alone, not also a difference between the bodies.
  out = refusal("robot lit = bot { }\n" + script("robot bot { control_step 200ms  ir_rangex 1cm }, lit"), "g.esc");
  EXPECT_NE(out.find("ir_rangex"), std::string::npos) << out;
  EXPECT_EQ(out.find("another `control_step`"), std::string::npos) << out;
  // A body derived from the first is told to match it, and where it differs.
  out = refusal("robot lit = bot { control_step 200ms }\n" + script("robot bot, lit"), "g.esc");
  EXPECT_NE(out.find("note: `lit`'s `control_step` is set here"), std::string::npos) << out;
  EXPECT_NE(out.find("help: give both bodies the same `control_step`"), std::string::npos) << out;
  // --set robot.KEY that breaks a further body's rules names that body.
  eval::ExperimentSpec x = first_experiment("robot lit = bot { ir_curve_x0 -1.5cm }\n" + script("robot bot, lit"), "g.esc");
  EXPECT_NE(apply_setting(x, "robot.ir_curve_c", "1cm2").find("body 2 of the group (`lit`)"), std::string::npos)
      << apply_setting(x, "robot.ir_curve_c", "1cm2");
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
