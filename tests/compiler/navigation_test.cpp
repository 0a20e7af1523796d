// The maze navigator in scripts (Lehman & Stanley 2011): segment walls and a goal in arenas,
// rangefinders and goal radars in robots, the observables that read them, and the errors of
// a script that reads a sensor its experiment lacks.
#include <gtest/gtest.h>

#include <numbers>
#include <string>

#include <fmt/format.h>

#include "helpers.hpp"
#include "runtime/eval/fingerprint.hpp"
#include "runtime/expr/observables.hpp"

namespace esc::compiler {
namespace {

using test::options;
using test::rendered;

constexpr double kDeg = std::numbers::pi / 180;

const char* kMaze = R"(
arena maze {
  size 1m x 60cm
  wall from (30cm, 0cm) to (30cm, 40cm)
  wall from (60cm, 60cm) to (60cm, 20cm) thickness 2cm
  goal at (90cm, 50cm)
  start at (10cm, 10cm) heading 90deg
}
robot navigator {
  rangefinders [90deg, 45deg, 0deg, -45deg, -90deg, 180deg]
  rangefinder_range 22cm
  radars 4
}
fitness near { step: 0  epoch: -goal_distance }
controller N = mlp(range[0..5], radar[0..3] -> hidden 5 -> wheels)
experiment e { arena maze  robot navigator  fitness near  compare N }
)";

eval::ExperimentSpec compiled(const std::string& script) { return test::first_experiment(script, "maze.esc"); }
std::string refused(const std::string& script) { return test::refusal(script, "maze.esc"); }

TEST(Navigation, WallsGoalAndSensorsInSi) {
  const eval::ExperimentSpec x = compiled(kMaze);
  ASSERT_EQ(x.arena.walls.size(), 2u);
  EXPECT_DOUBLE_EQ(x.arena.walls[0].from_m.x, 0.3);
  EXPECT_DOUBLE_EQ(x.arena.walls[0].to_m.y, 0.4);
  EXPECT_DOUBLE_EQ(x.arena.walls[0].thickness_m, sim::kDefaultWallThickness_m);
  EXPECT_DOUBLE_EQ(x.arena.walls[0].thickness_m, 0.01);
  EXPECT_DOUBLE_EQ(x.arena.walls[1].from_m.y, 0.6);
  EXPECT_DOUBLE_EQ(x.arena.walls[1].thickness_m, 0.02);
  ASSERT_TRUE(x.arena.goal.has_value());
  EXPECT_DOUBLE_EQ(x.arena.goal->x, 0.9);
  EXPECT_DOUBLE_EQ(x.arena.goal->y, 0.5);
  ASSERT_EQ(x.robot.rangefinders.angles_rad.size(), 6u);
  EXPECT_DOUBLE_EQ(x.robot.rangefinders.angles_rad[0], 90 * kDeg);
  EXPECT_DOUBLE_EQ(x.robot.rangefinders.angles_rad[3], -45 * kDeg);
  EXPECT_DOUBLE_EQ(x.robot.rangefinders.angles_rad[5], 180 * kDeg);
  EXPECT_DOUBLE_EQ(x.robot.rangefinders.range_m, 0.22);
  EXPECT_EQ(x.robot.radars, 4);
  // The network reads the six rangefinders, then the four radars.
  const auto& in = x.controllers.at(0).mlp.inputs;
  ASSERT_EQ(in.size(), 10u);
  EXPECT_EQ(in[0], expr::slot::range);
  EXPECT_EQ(in[5], expr::slot::range + 5);
  EXPECT_EQ(in[6], expr::slot::radar);
  EXPECT_EQ(in[9], expr::slot::radar + 3);
  EXPECT_EQ(x.resolved_settings.at("arena.walls"), "2");
  EXPECT_EQ(x.resolved_settings.at("arena.goal"), "(0.9 m, 0.5 m)");
  EXPECT_EQ(x.resolved_settings.at("robot.radars"), "4");
  EXPECT_EQ(x.resolved_settings.at("robot.rangefinder_range"), "0.22 m");
  EXPECT_EQ(x.resolved_settings.at("robot.rangefinders").substr(0, 22), "[1.5707963267948966 ra");
}

TEST(Navigation, WithoutThemTheResolvedSettingsHoldTheirAsBeforeValues) {
  const eval::ExperimentSpec x = test::paper();
  EXPECT_EQ(x.resolved_settings.at("arena.walls"), "0");
  EXPECT_EQ(x.resolved_settings.at("arena.goal"), "none");
  EXPECT_EQ(x.resolved_settings.at("robot.rangefinders"), "[]");
  EXPECT_EQ(x.resolved_settings.at("robot.rangefinder_range"), "0.34375 m");
  EXPECT_EQ(x.resolved_settings.at("robot.radars"), "0");
  // ... so the fingerprint leaves them out, as before they existed.
  const std::string f = eval::fingerprint(x);
  for (const char* key : {"arena.walls", "arena.goal", "robot.range", "robot.radars", "arena.wall "})
    EXPECT_EQ(f.find(key), std::string::npos) << key;
}

TEST(Navigation, PositionObservablesAreNamesInExpressions) {
  // `x` is the keyword of `60cm x 60cm` and `heading` of `start at ... heading`: names here.
  const eval::ExperimentSpec x = compiled(test::with_step("x + 2 * y - heading"));
  const auto code = x.fitness.step.code();
  ASSERT_EQ(code.size(), 7u);
  EXPECT_EQ(code[0].op, expr::Op::Load);
  EXPECT_EQ(code[0].slot, expr::slot::x);
  EXPECT_EQ(code[2].slot, expr::slot::y);
  EXPECT_EQ(code[5].slot, expr::slot::heading);
  // And as network inputs.
  const std::string script = std::string(kMaze).replace(std::string(kMaze).find("range[0..5]"), 11, "x, y, heading");
  EXPECT_EQ(compiled(script).controllers.at(0).mlp.inputs,
            (std::vector<expr::Slot>{expr::slot::x, expr::slot::y, expr::slot::heading, expr::slot::radar,
                                     expr::slot::radar + 1, expr::slot::radar + 2, expr::slot::radar + 3}));
}

// `kMaze` with `from` replaced by `to`.
std::string maze_with(const std::string& from, const std::string& to) {
  std::string s = kMaze;
  const auto at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return s.replace(at, from.size(), to);
}

TEST(Navigation, ArenaMistakesAreReportedAtTheItem) {
  EXPECT_NE(refused(maze_with("goal at (90cm, 50cm)", "goal at (90cm, 50cm)\n  goal at (10cm, 50cm)"))
                .find("maze.esc:7:3: error: the arena's goal is already given"),
            std::string::npos);
  EXPECT_NE(refused(maze_with("goal at (90cm, 50cm)", "goal at (90cm, 70cm)"))
                .find("maze.esc:6:3: error: the goal is outside the arena (100cm x 60cm): it reaches 10cm beyond a wall"),
            std::string::npos);
  EXPECT_NE(refused(maze_with("to (30cm, 40cm)", "to (30cm, 0cm)"))
                .find("maze.esc:4:3: error: a wall has a length: its two ends must not be the same point"),
            std::string::npos);
  EXPECT_NE(refused(maze_with("to (30cm, 40cm)", "to (30cm, 65cm)"))
                .find("maze.esc:4:3: error: this wall is not inside the arena (100cm x 60cm): it reaches 5cm beyond a wall"),
            std::string::npos);
  // Its thickness reaches past the walls too: 1 cm along the bottom wall's inside reaches 5 mm out.
  EXPECT_NE(refused(maze_with("to (30cm, 40cm)", "to (50cm, 0cm)")).find("it reaches 5mm beyond a wall"),
            std::string::npos);
}

TEST(Navigation, SensorSettingMistakes) {
  EXPECT_NE(refused(maze_with("[90deg, 45deg,", "[90deg, 90deg, 90deg, 90deg, 45deg,"))
                .find("maze.esc:10:16: error: a robot has at most 8 rangefinders, found 9"),
            std::string::npos);
  EXPECT_NE(refused(maze_with("rangefinder_range 22cm", "rangefinder_range 0cm"))
                .find("maze.esc:11:21: error: `rangefinder_range` must be greater than 0, found 0"),
            std::string::npos);
  EXPECT_NE(refused(maze_with("[90deg, 45deg, 0deg, -45deg, -90deg, 180deg]", "90deg"))
                .find("error: `rangefinders` takes a list, each value an angle, as in `[90deg, 0deg, -90deg]`, "
                      "found `90deg`"),
            std::string::npos);
  EXPECT_NE(refused(maze_with("[90deg, 45deg,", "[90, 45deg,")).find("maze.esc:10:17: error:"), std::string::npos);
}

TEST(Navigation, ReadingASensorTheExperimentLacksIsAnErrorAtTheRead) {
  // radar without a goal, in a fitness: at the read.
  std::string out = refused(maze_with("goal at (90cm, 50cm)", "") + "fitness r { step: radar[0] }\n"
                                                                    "experiment e2 { arena maze  robot navigator  "
                                                                    "fitness r  compare N }\n");
  EXPECT_NE(out.find("maze.esc:14:33: error: `goal_distance` needs the arena's goal, but arena `maze` has none"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("maze.esc:17:19: error: `radar[0]` needs the arena's goal, but arena `maze` has none"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("help: add `goal at (X, Y)` to arena `maze`"), std::string::npos) << out;
  // rangefinders the robot does not have, as network inputs: at the input.
  out = refused(maze_with("  rangefinders [90deg, 45deg, 0deg, -45deg, -90deg, 180deg]\n", ""));
  EXPECT_NE(out.find("maze.esc:14:20: error: `range[0]` reads rangefinder 0, but the robot of experiment `e` has "
                     "none"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("help: declare them in the robot's settings: `rangefinders [90deg, 45deg, 0deg, -45deg, -90deg, "
                     "180deg]`"),
            std::string::npos)
      << out;
  out = refused(maze_with("[90deg, 45deg, 0deg, -45deg, -90deg, 180deg]", "[90deg, 0deg, -90deg, 180deg]"));
  EXPECT_NE(out.find("`range[4]` reads rangefinder 4, but the robot of experiment `e` has 4 (`range[0]` .. "
                     "`range[3]`)"),
            std::string::npos)
      << out;
  // radar slices the robot does not have, in a behavior: at the read.
  out = refused(maze_with("radars 4", "radars 2") +
                "behavior seek() { wheels(radar[1], radar[2]) }\n"
                "controller S = supervisor(mlp(ir[0..7]), behaviors [seek])\n"
                "experiment e3 { arena maze  robot navigator  fitness near  compare S }\n");
  EXPECT_NE(out.find("maze.esc:17:36: error: `radar[2]` reads goal radar 2, but the robot of experiment `e3` has 2"),
            std::string::npos)
      << out;
}

TEST(Navigation, ASettingThatTakesASensorAwayIsRefused) {
  eval::ExperimentSpec x = compiled(kMaze);
  EXPECT_NE(apply_setting(x, "robot.radars", "0").find("`radar[0]` reads goal radar 0, but the robot of experiment "
                                                        "`e` has none"),
            std::string::npos);
  EXPECT_EQ(x.robot.radars, 4);   // unchanged
  EXPECT_NE(apply_setting(x, "robot.rangefinders", "[]").find("`range[0]` reads rangefinder 0"), std::string::npos);
  // Eight rangefinders, then two (a list of two is written as a range is).
  EXPECT_EQ(apply_setting(x, "robot.rangefinders", "[0deg, 45deg, 90deg, 135deg, 180deg, -135deg, -90deg, -45deg]"),
            "");
  EXPECT_EQ(x.robot.rangefinders.angles_rad.size(), 8u);
  EXPECT_DOUBLE_EQ(x.robot.rangefinders.angles_rad[7], -45 * kDeg);
  eval::ExperimentSpec y = compiled(maze_with("range[0..5], ", ""));
  EXPECT_EQ(apply_setting(y, "robot.rangefinders", "[10deg, -10deg]"), "");
  EXPECT_EQ(y.robot.rangefinders.angles_rad, (std::vector<double>{10 * kDeg, -10 * kDeg}));
  EXPECT_EQ(y.resolved_settings.at("robot.rangefinders"), fmt::format("[{} rad, {} rad]", 10 * kDeg, -10 * kDeg));
}

// The aggregates after the frame keep, in fingerprints, the numbers they had before the
// navigator's slots grew the frame (48 for `steps`), and the new slots are written apart
// (`f48` for `x`), so a stored run's fingerprint stays as it was and none is shared.
TEST(Navigation, FingerprintsNumberTheAggregatesAsBefore) {
  const int load = static_cast<int>(expr::Op::Load);
  const eval::ExperimentSpec steps = compiled(
      "arena a { size 1m x 1m }\nfitness g { step: 0  epoch: steps }\ncontroller c = mlp(ir[0..7] -> wheels)\n"
      "experiment h { arena a  fitness g  compare c }\n");
  EXPECT_NE(eval::fingerprint(steps).find(fmt::format("fitness.epoch {}:48:", load)), std::string::npos)
      << eval::fingerprint(steps);
  const eval::ExperimentSpec x = compiled(test::with_step("x"));
  EXPECT_NE(eval::fingerprint(x).find(fmt::format("fitness.step {}:f48:", load)), std::string::npos)
      << eval::fingerprint(x);
  // The walls and the goal are in it.
  const eval::ExperimentSpec m = compiled(kMaze);
  const std::string maze = eval::fingerprint(m);
  const sim::WallSegment& w = m.arena.walls[1];
  EXPECT_NE(maze.find(fmt::format("arena.wall {:a} {:a} {:a} {:a} {:a} \n", w.from_m.x, w.from_m.y, w.to_m.x, w.to_m.y,
                                  w.thickness_m)),
            std::string::npos)
      << maze;
  EXPECT_NE(maze.find(fmt::format("arena.goal {:a} {:a} \n", 0.9, 0.5)), std::string::npos) << maze;
  // Moving the goal changes it.
  EXPECT_NE(eval::fingerprint(compiled(maze_with("goal at (90cm, 50cm)", "goal at (90cm, 40cm)"))), maze);
}

TEST(Navigation, GpTerminalsReadTheSensorsTheExperimentHas) {
  const std::string gp = "primitives p { functions + - < if  terminals range[0..5], radar[0..3], goal_distance, x }\n"
                         "controller T = tree(wheels, primitives p)\n"
                         "experiment g { arena maze  robot navigator  fitness near  evolve gp(population 10)  "
                         "compare T }\n";
  const auto r = compile_source(std::string(kMaze) + gp, "maze.esc", options());
  ASSERT_TRUE(r.ok()) << rendered(r);
  const std::string out = refused(maze_with("radars 4", "radars 3") + gp);
  EXPECT_NE(out.find("maze.esc:18:40: error: `radar[3]` reads goal radar 3, but the robot of experiment `g` has 3"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("help: primitive set `p` holds it as a terminal"), std::string::npos) << out;
}

TEST(Navigation, TheExampleMazeCompilesCleanly) {
  const auto r = compile_file(test::source_dir() / "examples/maze.esc", options());
  ASSERT_TRUE(r.ok()) << rendered(r);
  EXPECT_TRUE(r.diagnostics.empty()) << rendered(r);
  const eval::ExperimentSpec& x = r.experiments.at(0);
  EXPECT_EQ(x.arena.walls.size(), 3u);
  EXPECT_EQ(x.robot.rangefinders.angles_rad.size(), 6u);
  EXPECT_EQ(x.robot.radars, 4);
  EXPECT_EQ(x.controllers.at(0).mlp.inputs.size(), 10u);
}

}  // namespace
}  // namespace esc::compiler
