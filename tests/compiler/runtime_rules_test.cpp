// One rule set: every rule of the runtime's validators (runtime/sim/validate.hpp) has a row
// here with a script that breaks it, and `esc check` refuses that script with the rule's
// message, in the script's words, at the setting that broke it. A rule added to the
// validators without a row fails EveryRuleHasARow.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "helpers.hpp"
#include "runtime/sim/validate.hpp"

namespace esc::compiler {
namespace {

using sim::Rule;
using test::options;
using test::rendered;

struct Row {
  Rule rule;
  std::string script;     // a script breaking the rule (and no other)
  std::string at;         // "LINE:COL" of the error
  std::string fragment;   // in the error's message
};

// Around a declaration that must be used by an experiment to be checked with a robot.
std::string in_experiment(const std::string& arena_items) {
  return "arena a {\n" + arena_items +
         "\n}\nfitness f { step: speed }\ncontroller c = mlp(ir[0..7] -> wheels)\n"
         "experiment e { arena a  fitness f  compare c }\n";
}

std::string many(const std::string& line, int n) {
  std::string s;
  for (int i = 0; i < n; ++i) s += line + "\n";
  return s;
}

std::string numbered(const std::string& before, const std::string& after, int n) {
  std::string s;
  for (int i = 0; i < n; ++i) s += before + std::to_string(i) + after + "\n";
  return s;
}

// A regular n-gon of radius 2 cm about the centre, a vertex a line.
std::string polygon(int n) {
  std::string s;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * std::numbers::pi * i / n;
    s += fmt::format("({:.4f}cm, {:.4f}cm){}\n", 2 * std::cos(t), 2 * std::sin(t), i + 1 < n ? "," : "");
  }
  return s;
}

const std::vector<Row>& rows() {
  static const std::vector<Row> table = {
      {Rule::ArenaWidth, "arena a { size -1m x 1m }", "1:16", "the arena's width must be greater than 0, found -100cm"},
      {Rule::ArenaHeight, "arena a { size 1m x 0m }", "1:21", "the arena's height must be greater than 0, found 0"},
      {Rule::ObstacleCount, "arena a { size 1m x 1m\n" + many("cylinder at (50cm, 50cm) radius 1cm", 30001) + "}",
       "30002:1", "an arena holds at most 30000 blocks, cylinders and walls together"},
      {Rule::BlockSize, "arena a { size 1m x 1m  block at (50cm, 50cm) size 0cm x 4cm }", "1:25",
       "a block's width and height must be greater than 0"},
      {Rule::BlockInside, "arena a { size 60cm x 60cm  block at (30cm, 1cm) size 10cm x 4cm }", "1:29",
       "this block is not inside the arena (60cm x 60cm): it reaches 1cm beyond a wall"},
      {Rule::CylinderRadius, "arena a { size 1m x 1m  cylinder at (50cm, 50cm) radius 0cm }", "1:57",
       "a cylinder's radius must be greater than 0"},
      {Rule::CylinderInside, "arena a { size 60cm x 60cm  cylinder at (59cm, 30cm) radius 2.5cm }", "1:29",
       "this cylinder is not inside the arena (60cm x 60cm): it reaches 1.5cm beyond a wall"},
      {Rule::WallLength, "arena a { size 1m x 1m  wall from (10cm, 10cm) to (10cm, 10cm) }", "1:25",
       "a wall has a length: its two ends must not be the same point"},
      {Rule::WallThickness, "arena a { size 1m x 1m  wall from (10cm, 10cm) to (50cm, 10cm) thickness 0cm }", "1:74",
       "a wall's thickness must be greater than 0, found 0"},
      {Rule::WallInside, "arena a { size 60cm x 60cm  wall from (10cm, 30cm) to (70cm, 30cm) }", "1:29",
       "this wall is not inside the arena (60cm x 60cm): it reaches 10cm beyond a wall"},
      {Rule::GoalInside, "arena a { size 60cm x 60cm  goal at (30cm, 65cm) }", "1:29",
       "the goal is outside the arena (60cm x 60cm): it reaches 5cm beyond a wall"},
      {Rule::StartInside, "arena a { size 60cm x 60cm  start at (70cm, 30cm) }", "1:29",
       "the start position is outside the arena (60cm x 60cm): it reaches 10cm beyond a wall"},
      {Rule::ZoneCount, "arena a { size 1m x 1m\n" + numbered("zone z", " circle radius 1cm at (50cm, 50cm)", 9) + "}",
       "10:1", "an arena holds at most 8 zones"},
      {Rule::ZoneRadius, "arena a { size 1m x 1m  zone z circle radius 0cm at (50cm, 50cm) }", "1:46",
       "a zone's radius must be greater than 0"},
      {Rule::ZoneSize, "arena a { size 1m x 1m  zone z rect 0cm x 10cm at (50cm, 50cm) }", "1:25",
       "a zone's width and height must be greater than 0"},
      {Rule::ZoneInside, "arena a { size 60cm x 60cm  zone z rect 20cm x 10cm at (55cm, 30cm) }", "1:29",
       "this zone is not inside the arena (60cm x 60cm): it reaches 5cm beyond a wall"},
      {Rule::ZoneFits, "arena a { size 60cm x 60cm  zone z rect 70cm x 10cm at random }", "1:29",
       "this zone is larger than the arena (60cm x 60cm)"},
      {Rule::LightCount, "arena a { size 1m x 1m\n" + numbered("light l", " at (50cm, 50cm)", 5) + "}", "6:1",
       "an arena holds at most 4 lights"},
      {Rule::LightHeight, "arena a { size 1m x 1m  light l at (50cm, 50cm) height -2cm }", "1:56",
       "a light's height must not be negative, found -2cm"},
      {Rule::LightIntensity, "arena a { size 1m x 1m  light l at (50cm, 50cm) intensity -1 }", "1:59",
       "a light's intensity must not be negative, found -1"},
      // The script names the zone: the compiler resolves the name before the rule can break.
      {Rule::LightZone, "arena a { size 1m x 1m  zone z circle radius 5cm at (50cm, 50cm)  light l above y }", "1:81",
       "unknown zone `y` in arena `a`"},
      {Rule::LightInside, "arena a { size 60cm x 60cm  light l at (70cm, 10cm) }", "1:29",
       "this light is not inside the arena (60cm x 60cm): it reaches 10cm beyond a wall"},
      {Rule::SweepCell, "arena a { size 1m x 1m  sweep_cell 0cm }", "1:36",
       "`sweep_cell` must be greater than 0, found 0"},
      {Rule::SweepGrid, "arena a { size 500m x 500m }", "1:11",
       "the area-sweeping grid of this arena (500m x 500m) would have 156250000 cells, more than the 100000000"},
      {Rule::ReachRadius, "arena a { size 1m x 1m  reach_radius -1cm }", "1:38",
       "`reach_radius` must be greater than 0, found -1cm"},
      {Rule::RobotFits,
       "arena a { size 5cm x 5cm }\nfitness f { step: speed }\ncontroller c = mlp(ir[0..7] -> wheels)\n"
       "experiment e {\n  arena a\n  fitness f\n  compare c\n}\n",
       "5:3", "the robot (5.5cm across) does not fit in arena `a` (5cm x 5cm)"},
      {Rule::StartClearOfWalls, in_experiment("  size 60cm x 60cm\n  start at (1cm, 30cm)"), "3:3",
       "the robot starting here would overlap a wall: its body radius is 2.75cm"},
      {Rule::StartClearOfCylinder,
       in_experiment("  size 60cm x 60cm\n  cylinder at (30cm, 30cm) radius 5cm\n  start at (32cm, 30cm)"), "4:3",
       "the robot starting here would overlap the cylinder at (30cm, 30cm)"},
      {Rule::StartClearOfBlock,
       in_experiment("  size 60cm x 60cm\n  block at (30cm, 30cm) size 10cm x 4cm\n  start at (30cm, 34cm)"), "4:3",
       "the robot starting here would overlap the block at (30cm, 30cm)"},
      {Rule::StartClearOfWall,
       in_experiment("  size 60cm x 60cm\n  wall from (10cm, 30cm) to (50cm, 30cm)\n  start at (30cm, 32cm)"), "4:3",
       "the robot starting here would overlap the wall from (10cm, 30cm) to (50cm, 30cm)"},
      {Rule::BodyRadius, "robot r { body_radius 0cm }", "1:23", "`body_radius` must be greater than 0, found 0"},
      {Rule::BodyHeight, "robot r { body_height -1cm }", "1:23", "`body_height` must be greater than 0, found -1cm"},
      {Rule::Mass, "robot r { mass 0g }", "1:16", "`mass` must be greater than 0, found 0"},
      {Rule::WheelBase, "robot r { wheel_base 0mm }", "1:22", "`wheel_base` must be greater than 0, found 0"},
      {Rule::WheelBaseWithinBody, "robot r { wheel_base 10cm }", "1:22",
       "the wheel base (10cm) is wider than the body (5.5cm across)"},
      {Rule::MaxSpeed, "robot r { max_speed -1cm/s }", "1:21", "`max_speed` must be greater than 0, found -1cm/s"},
      {Rule::TimeConstant, "robot r { time_constant -5ms }", "1:25", "`time_constant` must be at least 0, found -5ms"},
      {Rule::MaxAccel, "robot r { max_accel 0 m/s^2 }", "1:21", "`max_accel` must be greater than 0, found 0"},
      {Rule::IrRange, "robot r { ir_range -1cm }", "1:20", "`ir_range` must be greater than 0, found -1cm"},
      {Rule::IrApertureMin, "robot r { ir_aperture -1deg }", "1:23", "`ir_aperture` must be at least 0, found -1deg"},
      {Rule::IrApertureMax, "robot r { ir_aperture 200deg }", "1:23",
       "`ir_aperture` must be below 180deg, found 200deg"},
      {Rule::IrRaysMin, "robot r { ir_rays 0 }", "1:19", "`ir_rays` must be at least 1, found 0"},
      {Rule::IrRaysMax, "robot r { ir_rays 65 }", "1:19", "`ir_rays` must be at most 64, found 65"},
      {Rule::MotorNoise, "robot r { motor_noise -0.1 }", "1:23", "`motor_noise` must be at least 0, found -0.1"},
      {Rule::IrNoise, "robot r { ir_noise -0.1 }", "1:20", "`ir_noise` must be at least 0, found -0.1"},
      {Rule::IrCount, "robot r { ir_sensors [" + many("(0deg, 0deg),", 8) + "(0deg, 0deg)] }", "9:1",
       "a robot has at most 8 IR sensors, found 9"},
      {Rule::IrMountRadiusMin, "robot r { ir_sensors [(0deg, 0deg, -1mm)] }", "1:23",
       "IR sensor 0 sits -1mm from the body's centre: a distance is never negative"},
      {Rule::IrMountRadiusMax, "robot r { ir_sensors [(10deg, 0deg), (0deg, 0deg, 3cm)] }", "1:38",
       "IR sensor 1 sits 3cm from the body's centre, outside the body (radius 2.75cm)"},
      {Rule::IrCurve, "robot r { ir_curve_c 0.5cm2 }", "1:22",
       "Enki's IR curve needs `ir_curve_c` above `ir_curve_x0` squared; c - x0^2 is -0.31cm2"},
      {Rule::IrResponseCount, "robot r { ir_response [\n" + numbered("(", "mm, 0),", 64) + "(64mm, 0)] }", "66:1",
       "a measured IR response holds at most 64 points, found 65"},
      {Rule::IrResponseStart, "robot r { ir_response [(-1mm, 1), (5cm, 0)] }", "1:24",
       "the response's first distance is -1mm: a distance is never negative"},
      {Rule::IrResponseDistance, "robot r { ir_response [(0mm, 1), (2cm, 0.5), (1cm, 0)] }", "1:46",
       "the response's distances must increase: point 2 is at 1cm, the point before at 2cm"},
      {Rule::IrResponseReadingMin, "robot r { ir_response [(0mm, -0.5)] }", "1:24",
       "point 0 of the response reads -0.5: readings are normalised, 0 .. 1"},
      {Rule::IrResponseReadingMax, "robot r { ir_response [(0mm, 1), (1cm, 1.5)] }", "1:34",
       "point 1 of the response reads 1.5: readings are normalised, 0 .. 1"},
      {Rule::ControlStep, "robot r { control_step 0ms }", "1:24", "`control_step` must be greater than 0, found 0"},
      {Rule::SubstepsMin, "robot r { substeps 0 }", "1:20", "`substeps` must be at least 1, found 0"},
      {Rule::SubstepsMax, "robot r { substeps 1001 }", "1:20", "`substeps` must be at most 1000, found 1001"},
      {Rule::LightHalfDistance, "robot r { light_half_distance 0cm }", "1:31",
       "`light_half_distance` must be greater than 0, found 0"},
      {Rule::LightNoise, "robot r { light_noise -1 }", "1:23", "`light_noise` must be at least 0, found -1"},
      {Rule::EnergyDischargeMin, "robot r { energy_discharge 0 }", "1:28",
       "`energy_discharge` must be at least 1, found 0"},
      {Rule::EnergyDischargeMax, "robot r { energy_discharge 20000000 }", "1:28",
       "`energy_discharge` must be at most 10000000, found 20000000"},
      {Rule::EnergyRechargeMin, "robot r { energy_recharge -3 }", "1:27",
       "`energy_recharge` must be at least 1, found -3"},
      {Rule::EnergyRechargeMax, "robot r { energy_recharge 10000001 }", "1:27",
       "`energy_recharge` must be at most 10000000, found 10000001"},
      {Rule::RangefinderCount, "robot r { rangefinders [0deg, 0deg, 0deg, 0deg, 0deg, 0deg, 0deg, 0deg, 0deg] }",
       "1:24", "a robot has at most 8 rangefinders, found 9"},
      {Rule::RangefinderRange, "robot r { rangefinder_range 0cm }", "1:29",
       "`rangefinder_range` must be greater than 0, found 0"},
      {Rule::RadarsMin, "robot r { radars -1 }", "1:18", "`radars` must be at least 0, found -1"},
      {Rule::RadarsMax, "robot r { radars 9 }", "1:18", "`radars` must be at most 8, found 9"},
      // Inline in an experiment, on top of a declared robot: at the setting that broke it.
      {Rule::ContactLookAhead,
       "robot k { }\narena a { size 60cm x 60cm }\nfitness f { step: speed }\n"
       "controller c = mlp(ir[0..7] -> wheels)\nexperiment e { arena a\n robot k { max_speed 30 cm/s }\n fitness f\n"
       " compare c }\n",
       "6:22", "at full speed the rim of the robot moves 15.566mm per physics substep, more than the 10mm"},
      {Rule::TurnRate, "robot r { drive acceleration  max_turn_rate 0deg/s }", "1:45",
       "`max_turn_rate` must be greater than 0, found 0"},
      {Rule::TurnAccel, "robot r { drive acceleration  max_turn_accel -1deg/s^2 }", "1:46",
       "`max_turn_accel` must be greater than 0, found -1deg/s^2"},
      {Rule::NoiseWithoutWheels, "robot r { drive acceleration  motor_noise 0.1 }", "1:43",
       "`motor_noise` is an error of each wheel's speed, but this robot has the acceleration drive"},
      {Rule::OutlineCountMin, "robot r { body_outline [(1cm, 0cm), (0cm, 1cm)] }", "1:24",
       "an outline needs at least 3 vertices, found 2"},
      {Rule::OutlineCountMax, "robot r { body_outline [\n" + polygon(34) + "] }", "34:1",
       "an outline holds at most 32 vertices, found 34"},
      {Rule::OutlineConvex, "robot r { body_outline [(-1cm, -1cm), (1cm, -1cm), (0cm, 0cm), (1cm, 1cm), (-1cm, 1cm)] }",
       "1:52", "the outline is not convex at vertex 2"},
      {Rule::OutlineAroundCentre, "robot r { body_outline [(1cm, -1cm), (2cm, -1cm), (2cm, 1cm), (1cm, 1cm)] }",
       "1:24", "the outline does not hold the point the wheels turn about: that point lies 1cm outside an edge"},
      {Rule::OutlineWithinRadius, "robot r { body_outline [(-1cm, -2cm), (5cm, 0cm), (-1cm, 2cm)] }", "1:39",
       "outline vertex 1 lies 5cm from the centre, beyond `body_radius` (2.75cm)"},
      {Rule::GroundCount, "robot r { ground_sensors [(0deg, 1cm), (0deg, 1cm), (0deg, 1cm), (0deg, 1cm), (0deg, 1cm)] }",
       "1:79", "a robot has at most 4 ground sensors, found 5"},
      {Rule::GroundMountRadiusMin, "robot r { ground_sensors [(0deg, 1cm), (10deg, -1cm)] }", "1:40",
       "ground sensor 1 sits -1cm from the body's centre: a distance is never negative"},
      {Rule::GroundMountRadiusMax, "robot r { ground_sensors [(0deg, 4cm)] }", "1:27",
       "ground sensor 0 sits 4cm from the body's centre, outside the body (radius 2.75cm)"},
      {Rule::BumperCount,
       "robot r { bumpers [(0deg, 10deg), (0deg, 10deg), (0deg, 10deg), (0deg, 10deg), (0deg, 10deg)] }", "1:80",
       "a robot has at most 4 bumpers, found 5"},
      {Rule::BumperSectorMin, "robot r { bumpers [(45deg, -45deg)] }", "1:20",
       "bumper 0 spans -90deg from its first angle to its second"},
      {Rule::BumperSectorMax, "robot r { bumpers [(0deg, 400deg)] }", "1:20",
       "bumper 0 spans 400deg from its first angle to its second"},
      {Rule::OutlineCorner, "robot r { body_radius 9cm  substeps 4  body_outline [(8cm, 0cm), (-3cm, 0.5cm), (-3cm, -0.5cm)] }",
       "1:54", "the outline's corner at vertex 0 is 5.2"},
      {Rule::OutlineThin, "robot r { body_outline [(-1cm, -0.05cm), (1cm, -0.05cm), (1cm, 0.05cm), (-1cm, 0.05cm)] }",
       "1:24", "the outline is thinner than 2mm somewhere: moved in by 1mm, it turns inside out"},
      {Rule::GroundUnderOutline,
       "robot r { body_radius 9cm  substeps 4  body_outline [(-3cm, -5cm), (7cm, -5cm), (7cm, 5cm), (-3cm, 5cm)]\n"
       "  ground_sensors [(180deg, 6cm)] }",
       "2:19", "ground sensor 0 lies 3cm outside the body's outline"},
      {Rule::OutlineWithoutWheels, "robot r { drive acceleration  body_outline [(-1cm, -1cm), (1cm, 0cm), (-1cm, 1cm)] }",
       "1:44", "an outline needs the differential drive: the acceleration drive moves a disc"},
      {Rule::EmissionIntensity, "robot r { emission -0.5 }", "1:20", "`emission` must be at least 0, found -0.5"},
      {Rule::EmissionHeight, "robot r { emission 1  emission_height -1cm }", "1:39",
       "`emission_height` must be at least 0, found -1cm"},
  };
  return table;
}

TEST(RuntimeRules, EveryRuleHasARow) {
  std::set<Rule> covered;
  for (const Row& r : rows())
    EXPECT_TRUE(covered.insert(r.rule).second) << "two rows for rule " << static_cast<int>(r.rule);
  for (const sim::RuleInfo& info : sim::rules())
    EXPECT_EQ(covered.count(info.rule), 1u) << "no row for rule " << static_cast<int>(info.rule) << " ("
                                            << info.field << ")";
}

TEST(RuntimeRules, EsccheckRefusesAScriptBreakingEachRuleAtTheSetting) {
  for (const Row& r : rows()) {
    const auto result = compile_source(r.script, "rules.esc", options());
    const std::string out = rendered(result);
    const std::string want = "rules.esc:" + r.at + ": error: " + r.fragment;
    EXPECT_FALSE(result.ok()) << r.fragment;
    EXPECT_NE(out.find(want), std::string::npos) << "expected `" << want << "` in:\n" << out.substr(0, 2000);
    // In the script's words: never the runtime's field names.
    const sim::RuleInfo& info = sim::rule_info(r.rule);
    const std::string field(info.field.substr(0, info.field.find_first_of("[:")));
    EXPECT_EQ(out.find(field), std::string::npos) << out.substr(0, 2000);
    EXPECT_EQ(out.find("_m`"), std::string::npos) << out.substr(0, 2000);
  }
}

TEST(RuntimeRules, AGridTooFineIsShownAtTheSweepCellTheScriptChose) {
  const auto r = compile_source("arena a { size 60cm x 60cm  sweep_cell 0.01mm }", "grid.esc", options());
  const std::string out = rendered(r);
  EXPECT_NE(out.find("grid.esc:1:29: error: the area-sweeping grid of this arena (60cm x 60cm) would have 3600000000 "
                     "cells"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("help: write `sweep_cell 0.01cm` or larger"), std::string::npos) << out;
  EXPECT_EQ(out.find("sweep_cell_m"), std::string::npos) << out;
}

TEST(RuntimeRules, TheSweepCellSuggestedForAHugeArenaFits) {
  const auto r = compile_source("arena a { size 500m x 520m }", "fits.esc", options());
  EXPECT_FALSE(r.ok());
  const std::string out = rendered(r);
  const std::size_t at = out.find("help: write `sweep_cell ");
  ASSERT_NE(at, std::string::npos) << out;
  const std::string cell = out.substr(at + 24, out.find('`', at + 24) - at - 24);
  const auto fixed = compile_source("arena a { size 500m x 520m  sweep_cell " + cell + " }", "fits.esc", options());
  EXPECT_TRUE(fixed.ok()) << cell << "\n" << rendered(fixed);
  // And it is the smallest that does, to the centimetre's hundredth.
  const std::string smaller = fmt::format("{:.2f}cm", std::stod(cell) - 0.01);
  const auto refused = compile_source("arena a { size 500m x 520m  sweep_cell " + smaller + " }", "fits.esc", options());
  EXPECT_FALSE(refused.ok()) << smaller;
}

// A long, thin arena: the cell that fits (one row of cells) is far above the area's bound,
// where stepping up a hundredth of a centimetre at a time hung on a fuzzed script
// (tests/bad/sweep_grid_long_thin_arena.esc).
TEST(RuntimeRules, ALongThinArenaGetsTheSweepCellOfOneRow) {
  const auto r = compile_source("arena a { size 60cm x 1000000000m }", "thin.esc", options());
  const std::string out = rendered(r);
  EXPECT_NE(out.find("help: write `sweep_cell 1000cm` or larger"), std::string::npos) << out;
  const auto fixed = compile_source("arena a { size 60cm x 1000000000m  sweep_cell 1000cm }", "thin.esc", options());
  EXPECT_TRUE(fixed.ok()) << rendered(fixed);
}

// Every setting `--set` accepts goes through the same rules: what `esc check` accepts and
// `--set` leaves in place never fails the World's validation.
TEST(RuntimeRules, SetIsRefusedByTheSameRules) {
  const auto r = compile_file(test::source_dir() / "experiments/paper/obstacle_avoidance.esc", options());
  ASSERT_TRUE(r.ok()) << rendered(r);
  const eval::ExperimentSpec before = r.experiments.at(0);
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"robot.ir_aperture=200deg", "`ir_aperture` must be below 180deg, found 200deg"},
      {"robot.energy_discharge=20000000", "`energy_discharge` must be at most 10000000, found 20000000"},
      {"robot.max_speed=30cm/s", "at full speed the rim of the robot moves 15.566mm per physics substep"},
      {"arena.sweep_cell=0.001mm", "the area-sweeping grid of this arena (60cm x 60cm) would have"},
      {"arena.reach_radius=0cm", "`reach_radius` must be greater than 0, found 0"},
  };
  for (const auto& [kv, fragment] : bad) {
    eval::ExperimentSpec x = before;
    const std::size_t eq = kv.find('=');
    const std::string m = apply_setting(x, kv.substr(0, eq), kv.substr(eq + 1));
    EXPECT_NE(m.find(fragment), std::string::npos) << kv << ": " << m;
    EXPECT_EQ(x.resolved_settings, before.resolved_settings) << kv;
  }
  // The robot in the arena: a body wider than the arena (with substeps enough for its rim).
  eval::ExperimentSpec x = before;
  ASSERT_EQ(apply_setting(x, "robot.substeps", "100"), "");
  const std::string m = apply_setting(x, "robot.body_radius", "31cm");
  EXPECT_NE(m.find("the robot (62cm across) does not fit in arena `nolfi` (60cm x 60cm)"), std::string::npos) << m;
  EXPECT_DOUBLE_EQ(x.robot.body_radius_m, before.robot.body_radius_m);
}

TEST(RuntimeRules, EveryShippedExperimentPassesTheRuntimeRules) {
  int checked = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(test::source_dir() / "experiments")) {
    if (e.path().extension() != ".esc") continue;
    const auto r = compile_file(e.path(), options());
    ASSERT_TRUE(r.ok()) << e.path() << "\n" << rendered(r);
    for (const eval::ExperimentSpec& x : r.all_experiments) {
      EXPECT_TRUE(sim::arena_problems(x.arena).empty()) << x.name;
      EXPECT_TRUE(sim::robot_problems(x.robot).empty()) << x.name;
      EXPECT_TRUE(sim::placement_problems(x.arena, x.robot).empty()) << x.name;
      ++checked;
    }
  }
  EXPECT_GE(checked, 15);
}

}  // namespace
}  // namespace esc::compiler
