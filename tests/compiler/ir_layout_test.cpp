// IR sensors as data: a robot's `ir_sensors` (mounts), Enki's curve (`ir_curve_x0`,
// `ir_curve_c`) or a measured `ir_response`, read in SI; the Khepera's own values restated
// give exactly the default robot; mistakes are located at the tuple; reading a sensor the
// robot does not have is an error at the read.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "helpers.hpp"
#include "runtime/eval/fingerprint.hpp"
#include "runtime/expr/observables.hpp"

namespace esc::compiler {
namespace {

using test::options;
using test::rendered;

constexpr double kDeg = std::numbers::pi / 180;

// A robot with three sensors, one of them 1 cm inside the rim, and a measured response.
std::string script(const std::string& robot_settings, const std::string& inputs = "ir[0..2]") {
  return "arena a { size 1m x 1m }\n"
         "robot r {\n" + robot_settings + "\n}\n"
         "fitness f { step: speed }\n"
         "controller c = mlp(" + inputs + " -> wheels)\n"
         "experiment e { arena a  robot r  fitness f  compare c }\n";
}

const std::string kThree =
    "  ir_sensors [(45deg, 45deg), (0deg, 0deg, 1.75cm), (-45deg, -45deg)]\n"
    "  ir_response [(0mm, 1), (1cm, 0.6), (3cm, 0.1)]";

eval::ExperimentSpec compiled(const std::string& text) { return test::first_experiment(text, "ir.esc"); }
std::string refused(const std::string& text) { return test::refusal(text, "ir.esc"); }

TEST(IrLayout, MountsAndResponseInSi) {
  const eval::ExperimentSpec x = compiled(script(kThree));
  const auto& m = x.robot.ir.mounts;
  ASSERT_EQ(m.size(), 3u);
  EXPECT_DOUBLE_EQ(m[0].bearing_rad, 45 * kDeg);
  EXPECT_DOUBLE_EQ(m[0].facing_rad, 45 * kDeg);
  EXPECT_FALSE(m[0].radius_m.has_value());
  ASSERT_TRUE(m[1].radius_m.has_value());
  EXPECT_DOUBLE_EQ(*m[1].radius_m, 0.0175);
  EXPECT_DOUBLE_EQ(m[2].facing_rad, -45 * kDeg);
  ASSERT_EQ(x.robot.ir.response.size(), 3u);
  EXPECT_DOUBLE_EQ(x.robot.ir.response[1].distance_m, 0.01);
  EXPECT_DOUBLE_EQ(x.robot.ir.response[1].reading, 0.6);
  EXPECT_EQ(x.resolved_settings.at("robot.ir_response"), "[(0 m, 1), (0.01 m, 0.6), (0.03 m, 0.1)]");
}

// The default robot's new settings read as they did before they existed, so fingerprints
// (and cached evaluations) of earlier runs stay valid.
TEST(IrLayout, TheDefaultsAreTheirAsBeforeValues) {
  const eval::ExperimentSpec x = test::paper();
  EXPECT_EQ(x.resolved_settings.at("robot.ir_response"), "[]");
  EXPECT_EQ(x.resolved_settings.at("robot.ir_curve_c"), "0.0007 m2");
  const std::string f = eval::fingerprint(x);
  for (const char* key : {"robot.ir_sensors", "robot.ir_curve", "robot.ir_response"})
    EXPECT_EQ(f.find(key), std::string::npos) << key;
}

// The Khepera's layout and curve written out in a script are the default robot, bit for bit.
TEST(IrLayout, TheKheperaRestatedIsTheDefault) {
  const eval::ExperimentSpec restated = compiled(script(
      "  ir_sensors [(68deg, 90deg), (43deg, 45deg), (13deg, 10deg), (-13deg, -10deg), (-43deg, -45deg),\n"
      "              (-68deg, -90deg), (158deg, 180deg), (-158deg, 180deg)]\n"
      "  ir_curve_x0 -0.9cm\n"
      "  ir_curve_c 7cm2",
      "ir[0..7]"));
  const sim::RobotParams khepera;
  EXPECT_EQ(restated.robot.ir.mounts, khepera.ir.mounts);
  EXPECT_EQ(restated.robot.ir.curve_x0_cm, khepera.ir.curve_x0_cm);
  EXPECT_EQ(restated.robot.ir.curve_c_cm2, khepera.ir.curve_c_cm2);
}

TEST(IrLayout, MistakesAreLocated) {
  std::string out = refused(script("  ir_sensors [(45deg, 45deg), (0deg)]"));
  EXPECT_NE(out.find("ir.esc:3:31: error: each tuple of `ir_sensors` holds 2 or 3 values, this one 1"),
            std::string::npos)
      << out;
  out = refused(script("  ir_sensors [45deg, 0deg]"));
  EXPECT_NE(out.find("ir.esc:3:14: error: `ir_sensors` takes a list of tuples, as in `[(68deg, 90deg), (43deg, "
                     "45deg, 27mm)]`, found `[45deg, 0deg]`"),
            std::string::npos)
      << out;
  out = refused(script("  ir_sensors [(45deg, 45deg), (0deg, 2cm)]"));
  EXPECT_NE(out.find("ir.esc:3:39: error: expected an angle, found a length (`cm`)"), std::string::npos) << out;
  out = refused(script("  ir_response [(0cm, 1), (2cm)]"));
  EXPECT_NE(out.find("ir.esc:3:26: error: each tuple of `ir_response` holds 2 values, this one 1"), std::string::npos)
      << out;
}

TEST(IrLayout, ReadingASensorTheRobotLacksIsAnErrorAtTheRead) {
  std::string out = refused(script(kThree, "ir[0..7]"));
  EXPECT_NE(out.find("ir.esc:7:20: error: `ir[3]` reads IR sensor 3, but the robot of experiment `e` has 3 (`ir[0]` .. "
                     "`ir[2]`)"),
            std::string::npos)
      << out;
  out = refused(script("  ir_sensors []", "light[0]"));
  EXPECT_NE(out.find("`light[0]` reads light sensor 0, but the robot of experiment `e` has none"), std::string::npos)
      << out;
  eval::ExperimentSpec x = compiled(script(kThree));
  EXPECT_NE(apply_setting(x, "robot.ir_sensors", "[(0deg, 0deg), (10deg, 10deg)]").find("`ir[2]` reads IR sensor 2"),
            std::string::npos);
  EXPECT_EQ(apply_setting(x, "robot.ir_sensors", "[(0deg, 0deg), (10deg, 10deg), (20deg, 20deg, 2cm)]"), "");
  ASSERT_EQ(x.robot.ir.mounts.size(), 3u);
  EXPECT_DOUBLE_EQ(*x.robot.ir.mounts[2].radius_m, 0.02);
}

// The robot names its sensors: a controller written with the e-puck's `prox` reads the same
// frame slots as `ir`, and on a body whose sensors are called otherwise it is an error at the read.
const std::string kTwoBodies =
    "arena a { size 1m x 1m }\n"
    "robot puck { ir_name prox }\n"
    "fitness f { step: speed * (1 - prox[0]) }\n"
    "controller p = mlp(prox[0..7] -> wheels)\n"
    "primitives terms { functions + *  terminals prox[0..1], speed }\n"
    "controller t = tree(wheels, primitives terms)\n"
    "experiment e {\n  arena a  robot puck  fitness f\n  evolve es(mu 2, lambda 4)  evolve gp(population 10)\n  compare p, t\n}\n";

TEST(SensorNames, TheRobotNamesItsSensors) {
  const eval::ExperimentSpec x = compiled(kTwoBodies);
  EXPECT_EQ(x.robot.ir.name, "prox");
  ASSERT_EQ(x.controllers.at(0).mlp.inputs.size(), 8u);
  EXPECT_EQ(x.controllers.at(0).mlp.inputs[3], expr::slot::ir + 3);
  EXPECT_EQ(x.resolved_settings.at("robot.ir_name"), "prox");
  EXPECT_EQ(test::paper().resolved_settings.at("robot.ir_name"), "ir");
}

TEST(SensorNames, AControllerForAnotherBodyIsAnErrorAtTheRead) {
  std::string out = refused(kTwoBodies + "experiment k { arena a  fitness f  compare p }\n");
  EXPECT_NE(out.find("ir.esc:3:32: error: `prox` names IR sensors, but the robot of experiment `k` calls its IR "
                     "sensors `ir`"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("ir.esc:4:20: error: `prox` names IR sensors, but the robot of experiment `k` calls its IR "
                     "sensors `ir`"),
            std::string::npos)
      << out;
  out = refused(kTwoBodies + "controller c = mlp(ir[0..7] -> wheels)\nexperiment k { arena a  robot puck  fitness f  "
                             "compare c }\n");
  EXPECT_NE(out.find("ir.esc:12:20: error: `ir` names IR sensors, but the robot of experiment `k` calls its IR sensors "
                     "`prox`"),
            std::string::npos)
      << out;
  out = refused(kTwoBodies + "fitness g { step: 1 }\nexperiment k { arena a  fitness g  evolve gp(population 10)  "
                             "compare t }\n");
  EXPECT_NE(out.find("ir.esc:6:40: error: `prox` names IR sensors, but the robot of experiment `k`"), std::string::npos)
      << out;
}

TEST(SensorNames, ANameMustBeItsOwnAndIsSetInARobotBlock) {
  std::string out = refused(script("  ir_name speed"));
  EXPECT_NE(out.find("ir.esc:3:11: error: `speed` is an observable of every robot; these sensors need a name of their "
                     "own"),
            std::string::npos)
      << out;
  out = refused(script("  ir_name 3"));
  EXPECT_NE(out.find("ir.esc:3:11: error: `ir_name` takes a name, as in `ir_name prox`, found `3`"), std::string::npos)
      << out;
  eval::ExperimentSpec x = compiled(kTwoBodies);
  EXPECT_NE(apply_setting(x, "robot.ir_name", "ir").find("it is set in a robot block, not with --set"),
            std::string::npos);
  EXPECT_EQ(x.robot.ir.name, "prox");
}

// The standard library's e-puck: the constants docs/robot-model.md cites, read as written.
TEST(SensorNames, TheLibrarysEpuckIsAsCited) {
  const auto r = compile_file(test::source_dir() / "experiments/bodies/epuck_obstacle_avoidance.esc", options());
  ASSERT_TRUE(r.ok()) << rendered(r);
  const sim::RobotParams& puck = r.experiments.at(0).robot;
  EXPECT_DOUBLE_EQ(puck.body_radius_m, 0.037);
  EXPECT_DOUBLE_EQ(puck.wheel_base_m, 0.053);
  EXPECT_DOUBLE_EQ(puck.motor.max_speed_mps, 0.128);
  EXPECT_FALSE(puck.motor.inertia);
  EXPECT_EQ(puck.ir.name, "prox");
  ASSERT_EQ(puck.ir.mounts.size(), 8u);
  // Enki's (3.35, -1.05) cm, its bearing written to the thousandth of a degree (0.2 µm at the rim).
  EXPECT_NEAR(puck.ir.mounts[0].bearing_rad, std::atan2(-1.05, 3.35), 1e-5);
  EXPECT_NEAR(*puck.ir.mounts[0].radius_m, std::hypot(0.0335, 0.0105), 1e-6);
  EXPECT_DOUBLE_EQ(puck.ir.mounts[3].facing_rad, -142 * kDeg);
  EXPECT_EQ(puck.ir.curve_x0_cm, 0.3);
  EXPECT_EQ(puck.ir.curve_c_cm2, 0.7);
  EXPECT_DOUBLE_EQ(puck.ir.range_m, 0.12);
}

// The standard library's navigator: the acceleration drive with the authors' numbers in their
// units scaled (docs/robot-model.md), their sensors, no IR; a network reading `ir` is refused.
TEST(Bodies, TheLibrarysNavigatorIsAsCited) {
  const std::string maze =
      "import \"lib/navigator.esc\"\n"
      "arena m { size 1m x 60cm  wall from (30cm, 0cm) to (30cm, 40cm)  goal at (90cm, 50cm)  start at (10cm, 10cm) }\n"
      "fitness near { step: 0  epoch: -goal_distance }\n"
      "controller N = neat(range[0..5], radar[0..3] -> wheels)\n"
      "experiment e { arena m  robot navigator  fitness near  evolve neat(population 20)  compare N }\n";
  const eval::ExperimentSpec x = compiled(maze);
  const sim::RobotParams& n = x.robot;
  EXPECT_EQ(n.drive, sim::DriveKind::Acceleration);
  constexpr double kUnit = 0.0034375, kStep = 0.1;
  EXPECT_DOUBLE_EQ(n.body_radius_m, 8 * kUnit);
  EXPECT_DOUBLE_EQ(n.motor.max_speed_mps, 3 * kUnit / kStep);
  EXPECT_DOUBLE_EQ(n.motor.max_accel_mps2 * kStep * kStep, 0.5 * kUnit);
  EXPECT_DOUBLE_EQ(n.turn.max_rate_radps * kStep, 3 * kDeg);
  EXPECT_NEAR(n.turn.max_accel_radps2 * kStep * kStep, 0.5 * kDeg, 1e-15);
  EXPECT_TRUE(n.ir.mounts.empty());
  EXPECT_EQ(n.rangefinders.angles_rad.size(), 6u);
  EXPECT_EQ(n.radars, 4);
  EXPECT_EQ(x.resolved_settings.at("robot.drive"), "acceleration");
  const std::string out = refused(maze + "controller K = mlp(ir[0..1] -> wheels)\n"
                                         "experiment k { arena m  robot navigator  fitness near  compare K }\n");
  EXPECT_NE(out.find("`ir[0]` reads IR sensor 0, but the robot of experiment `k` has none"), std::string::npos) << out;
}

// Ground sensors: their points read in SI, their name the robot's (`prox_ground` on the
// Thymio), a network input by that name, and a read beyond them or by another body's name an
// error at the read.
const std::string kGrounded =
    "arena a { size 1m x 1m }\n"
    "robot t { ground_name prox_ground  ground_sensors [(9deg, 2.3cm), (-9deg, 2.3cm)] }\n"
    "fitness f { step: speed * (1 - prox_ground[0]) }\n"
    "controller g = mlp(prox_ground[0..1], ir[0..1] -> wheels)\n"
    "experiment e { arena a  robot t  fitness f  compare g }\n";

TEST(GroundSensors, NamedByTheRobotAndReadInSi) {
  const eval::ExperimentSpec x = compiled(kGrounded);
  ASSERT_EQ(x.robot.ground.mounts.size(), 2u);
  EXPECT_DOUBLE_EQ(x.robot.ground.mounts[1].bearing_rad, -9 * kDeg);
  EXPECT_DOUBLE_EQ(x.robot.ground.mounts[1].radius_m, 0.023);
  EXPECT_EQ(x.robot.ground.name, "prox_ground");
  EXPECT_EQ(x.controllers.at(0).mlp.inputs.at(1), expr::slot::ground_sensor + 1);
  EXPECT_EQ(test::paper().resolved_settings.at("robot.ground_sensors"), "[]");
  EXPECT_EQ(test::paper().resolved_settings.at("robot.ground_name"), "ground_sensor");
}

// A name reads one array in the whole program: a second array by it is refused where it is
// given, whichever robot comes first.
TEST(GroundSensors, ANameNamesOneArray) {
  const std::string two = "robot e { ir_name prox }\nrobot t { ground_name prox }\n";
  std::string out = refused(two + "arena a { size 1m x 1m }\nfitness f { step: speed }\n"
                                  "controller c = mlp(prox[0..1] -> wheels)\n"
                                  "experiment x { arena a  robot e  fitness f  compare c }\n");
  EXPECT_NE(out.find("ir.esc:2:23: error: `prox` already names IR sensors (`ir_name prox`); the ground sensors need a "
                     "name of their own"),
            std::string::npos)
      << out;
  out = refused("robot t { ir_name s  ground_name s }\narena a { size 1m x 1m }\nfitness f { step: speed }\n"
                "controller c = mlp(s[0..1] -> wheels)\nexperiment x { arena a  robot t  fitness f  compare c }\n");
  EXPECT_NE(out.find("ir.esc:1:34: error: `s` already names IR sensors"), std::string::npos) << out;
}

TEST(GroundSensors, AReadBeyondThemOrByAnotherNameIsAnErrorAtTheRead) {
  std::string text = kGrounded;
  text.replace(text.find("prox_ground[0..1]"), 17, "prox_ground[0..2]");
  std::string out = refused(text);
  EXPECT_NE(out.find("ir.esc:4:20: error: `prox_ground[2]` reads ground sensor 2, but the robot of experiment `e` "
                     "has 2 (`prox_ground[0]` .. `prox_ground[1]`)"),
            std::string::npos)
      << out;
  out = refused(kGrounded + "experiment k { arena a  fitness f  compare g }\n");
  EXPECT_NE(out.find("`prox_ground` names ground sensors, but the robot of experiment `k` calls its ground sensors "
                     "`ground_sensor`"),
            std::string::npos)
      << out;
}

}  // namespace
}  // namespace esc::compiler
