// Invalid arenas and robots are rejected at construction, naming the field.
#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "sim_test_util.hpp"

namespace esc::sim {
namespace {

struct Case {
  std::string field;
  std::function<void(ArenaSpec&, KheperaParams&)> spoil;
};

TEST(SimParams, InvalidValuesThrowNamingTheField) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Case> cases = {
      {"arena.width_m", [](ArenaSpec& a, KheperaParams&) { a.width_m = 0.0; }},
      {"arena.height_m", [](ArenaSpec& a, KheperaParams&) { a.height_m = -1.0; }},
      {"arena.height_m", [nan](ArenaSpec& a, KheperaParams&) { a.height_m = nan; }},
      {"arena.boxes[0].size_m",
       [](ArenaSpec& a, KheperaParams&) { a.boxes.push_back({{0.1, 0.1}, {0.1, 0.0}, 0.0}); }},
      {"arena.cylinders[1].radius_m",
       [](ArenaSpec& a, KheperaParams&) {
         a.cylinders.push_back({{0.1, 0.1}, 0.02});
         a.cylinders.push_back({{0.3, 0.1}, -0.02});
       }},
      {"robot.body_radius_m", [](ArenaSpec&, KheperaParams& r) { r.body_radius_m = 0.0; }},
      {"robot.body_height_m", [](ArenaSpec&, KheperaParams& r) { r.body_height_m = -0.03; }},
      {"robot.mass_kg", [](ArenaSpec&, KheperaParams& r) { r.mass_kg = 0.0; }},
      {"robot.wheel_base_m", [](ArenaSpec&, KheperaParams& r) { r.wheel_base_m = 0.0; }},
      {"robot.motor.max_speed_mps", [](ArenaSpec&, KheperaParams& r) { r.motor.max_speed_mps = -0.1; }},
      {"robot.motor.time_constant_s", [](ArenaSpec&, KheperaParams& r) { r.motor.time_constant_s = -1; }},
      {"robot.motor.max_accel_mps2", [](ArenaSpec&, KheperaParams& r) { r.motor.max_accel_mps2 = 0; }},
      {"robot.ir.range_m", [](ArenaSpec&, KheperaParams& r) { r.ir.range_m = 0.0; }},
      {"robot.ir.aperture_rad", [](ArenaSpec&, KheperaParams& r) { r.ir.aperture_rad = 4.0; }},
      {"robot.ir.rays", [](ArenaSpec&, KheperaParams& r) { r.ir.rays = 0; }},
      {"robot.ir.noise_sd", [](ArenaSpec&, KheperaParams& r) { r.ir.noise_sd = -0.1; }},
      {"robot.control_step_s", [](ArenaSpec&, KheperaParams& r) { r.control_step_s = 0.0; }},
      {"robot.physics_substeps", [](ArenaSpec&, KheperaParams& r) { r.physics_substeps = 0; }},
      // 1 m/s over 50 ms substeps: 5 cm per substep, beyond the contact look-ahead.
      {"robot.physics_substeps", [](ArenaSpec&, KheperaParams& r) { r.motor.max_speed_mps = 1.0; }},
  };
  for (const Case& c : cases) {
    ArenaSpec arena = test::empty_arena(0.6, 0.6);
    KheperaParams robot;
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
  KheperaParams robot;
  robot.motor.time_constant_s = 0.0;  // acceleration limit only
  robot.ir.rays = 1;
  robot.ir.aperture_rad = 0.0;
  robot.physics_substeps = 1;
  EXPECT_NO_THROW(World(test::empty_arena(0.6, 0.6), robot));
  EXPECT_NO_THROW(World(test::empty_arena(0.6, 0.6), KheperaParams{}));
}

}  // namespace
}  // namespace esc::sim
