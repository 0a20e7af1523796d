// Invalid arenas and robots are rejected at construction, naming the field; the same rules
// as data (sim::arena_problems, robot_problems, placement_problems).
#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "runtime/sim/validate.hpp"
#include "sim_test_util.hpp"

namespace esc::sim {
namespace {

struct Case {
  std::string field;
  std::function<void(ArenaSpec&, RobotParams&)> spoil;
};

TEST(SimParams, InvalidValuesThrowNamingTheField) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Case> cases = {
      {"arena.width_m", [](ArenaSpec& a, RobotParams&) { a.width_m = 0.0; }},
      {"arena.height_m", [](ArenaSpec& a, RobotParams&) { a.height_m = -1.0; }},
      {"arena.height_m", [nan](ArenaSpec& a, RobotParams&) { a.height_m = nan; }},
      {"arena.boxes[0].size_m",
       [](ArenaSpec& a, RobotParams&) { a.boxes.push_back({{0.1, 0.1}, {0.1, 0.0}, 0.0}); }},
      {"arena.cylinders[1].radius_m",
       [](ArenaSpec& a, RobotParams&) {
         a.cylinders.push_back({{0.1, 0.1}, 0.02});
         a.cylinders.push_back({{0.3, 0.1}, -0.02});
       }},
      {"robot.body_radius_m", [](ArenaSpec&, RobotParams& r) { r.body_radius_m = 0.0; }},
      {"robot.body_height_m", [](ArenaSpec&, RobotParams& r) { r.body_height_m = -0.03; }},
      {"robot.mass_kg", [](ArenaSpec&, RobotParams& r) { r.mass_kg = 0.0; }},
      {"robot.wheel_base_m", [](ArenaSpec&, RobotParams& r) { r.wheel_base_m = 0.0; }},
      {"robot.motor.max_speed_mps", [](ArenaSpec&, RobotParams& r) { r.motor.max_speed_mps = -0.1; }},
      {"robot.motor.time_constant_s", [](ArenaSpec&, RobotParams& r) { r.motor.time_constant_s = -1; }},
      {"robot.motor.max_accel_mps2", [](ArenaSpec&, RobotParams& r) { r.motor.max_accel_mps2 = 0; }},
      {"robot.ir.range_m", [](ArenaSpec&, RobotParams& r) { r.ir.range_m = 0.0; }},
      {"robot.ir.aperture_rad", [](ArenaSpec&, RobotParams& r) { r.ir.aperture_rad = 4.0; }},
      {"robot.ir.rays", [](ArenaSpec&, RobotParams& r) { r.ir.rays = 0; }},
      {"robot.ir.noise_sd", [](ArenaSpec&, RobotParams& r) { r.ir.noise_sd = -0.1; }},
      {"robot.control_step_s", [](ArenaSpec&, RobotParams& r) { r.control_step_s = 0.0; }},
      {"robot.physics_substeps", [](ArenaSpec&, RobotParams& r) { r.physics_substeps = 0; }},
      // 1 m/s over 50 ms substeps: 5 cm per substep, beyond the contact look-ahead.
      {"robot.physics_substeps", [](ArenaSpec&, RobotParams& r) { r.motor.max_speed_mps = 1.0; }},
  };
  for (const Case& c : cases) {
    ArenaSpec arena = test::empty_arena(0.6, 0.6);
    RobotParams robot;
    c.spoil(arena, robot);
    try {
      World world(arena, robot);
      ADD_FAILURE() << "no exception for " << c.field;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(c.field), std::string::npos)
          << "message '" << e.what() << "' does not name " << c.field;
    }
  }
}

TEST(SimParams, DefaultsAndEdgeValuesAreAccepted) {
  RobotParams robot;
  robot.motor.time_constant_s = 0.0;  // acceleration limit only
  robot.ir.rays = 1;
  robot.ir.aperture_rad = 0.0;
  robot.physics_substeps = 1;
  EXPECT_NO_THROW(World(test::empty_arena(0.6, 0.6), robot));
  EXPECT_NO_THROW(World(test::empty_arena(0.6, 0.6), RobotParams{}));
}

}  // namespace
}  // namespace esc::sim

namespace esc::sim {
namespace {

// The rules as data: every broken rule at once, with what it is about, the value found and
// the limit, without throwing.
TEST(SimRules, ProblemsListEveryBrokenRuleWithItsValueAndLimit) {
  EXPECT_TRUE(arena_problems(test::empty_arena(0.6, 0.6)).empty());
  EXPECT_TRUE(robot_problems(RobotParams{}).empty());
  EXPECT_TRUE(placement_problems(test::empty_arena(0.6, 0.6), RobotParams{}).empty());

  ArenaSpec a = test::empty_arena(0.6, 0.6);
  a.cylinders.push_back({{0.59, 0.3}, 0.025});   // reaches 1.5 cm beyond the right wall
  a.lights.push_back({{0.3, 0.3}, 0.0, -1.0, -1});
  const auto arena = arena_problems(a);
  ASSERT_EQ(arena.size(), 2u);
  EXPECT_EQ(arena[0].rule, Rule::CylinderInside);
  EXPECT_EQ(arena[0].index, 0);
  EXPECT_NEAR(arena[0].found, 0.015, 1e-12);
  EXPECT_EQ(arena[1].rule, Rule::LightIntensity);
  EXPECT_EQ(arena[1].info().setting, "light");
  EXPECT_DOUBLE_EQ(arena[1].found, -1.0);

  RobotParams r;
  r.ir.aperture_rad = 4.0;
  r.energy.discharge_steps = 20'000'000;
  const auto robot = robot_problems(r);
  ASSERT_EQ(robot.size(), 2u);
  EXPECT_EQ(robot[0].rule, Rule::IrApertureMax);
  EXPECT_EQ(robot[0].info().setting, "ir_aperture");
  EXPECT_EQ(robot[0].info().dimension, Dimension::Angle);
  EXPECT_DOUBLE_EQ(robot[0].limit, std::numbers::pi);
  EXPECT_EQ(robot[1].rule, Rule::EnergyDischargeMax);
  EXPECT_DOUBLE_EQ(robot[1].limit, kMaxEnergySteps);
}

// The World's guard throws the first problem's message; the rim, not the centre, counts.
TEST(SimRules, TheGuardThrowsTheFirstProblemAndTheRimCounts) {
  RobotParams r;
  r.motor.max_speed_mps = 0.19;   // centre 9.5 mm per substep, rim 9.86 mm: fine
  EXPECT_TRUE(robot_problems(r).empty());
  r.motor.max_speed_mps = 0.195;  // centre 9.75 mm, rim 10.12 mm: too far
  const auto problems = robot_problems(r);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].rule, Rule::ContactLookAhead);
  EXPECT_NEAR(problems[0].found, 0.195 * (0.055 / 0.053) * 0.05, 1e-12);
  try {
    validate_robot(r);
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), problems[0].message());
  }
  r = RobotParams{};
  r.wheel_base_m = 0.06;   // wider than the 55 mm body
  ASSERT_EQ(robot_problems(r).size(), 1u);
  EXPECT_EQ(robot_problems(r)[0].rule, Rule::WheelBaseWithinBody);
}

TEST(SimRules, TheRobotInTheArena) {
  ArenaSpec a = test::empty_arena(0.05, 0.6);
  EXPECT_EQ(placement_problems(a, RobotParams{}).at(0).rule, Rule::RobotFits);
  a = test::empty_arena(0.6, 0.6);
  a.cylinders.push_back({{0.3, 0.3}, 0.05});
  a.fixed_start = Pose{0.32, 0.3, 0.0};
  const auto p = placement_problems(a, RobotParams{});
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0].rule, Rule::StartClearOfCylinder);
  EXPECT_NEAR(p[0].found, -0.03, 1e-12);   // the centre is 3 cm inside the cylinder
  EXPECT_DOUBLE_EQ(p[0].limit, RobotParams{}.body_radius_m);
}

}  // namespace
}  // namespace esc::sim
