// The acceleration drive (Lehman & Stanley's maze navigator): the commands accelerate the
// turn rate and the speed up to their tops, the centre moves along the heading the step began
// with, and a move that would bring it within its radius of a wall is cancelled. Checked
// against their update (maze.h, Character and Update) written out here in their units, maze
// units and degrees per step, 1 unit = 3.4375 mm and a step of 100 ms.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "sim_test_util.hpp"

namespace esc::sim {
namespace {

constexpr double kUnit = 0.0034375;   // metres per maze unit
constexpr double kDeg = std::numbers::pi / 180.0;

RobotParams navigator() {
  RobotParams r;
  r.drive = DriveKind::Acceleration;
  r.body_radius_m = 8 * kUnit;
  r.motor.max_speed_mps = 3 * kUnit / r.control_step_s;                          // 3 units a step
  r.motor.max_accel_mps2 = 0.5 * kUnit / (r.control_step_s * r.control_step_s);  // 0.5 units a step per step
  r.turn.max_rate_radps = 3 * kDeg / r.control_step_s;
  r.turn.max_accel_radps2 = 0.5 * kDeg / (r.control_step_s * r.control_step_s);
  r.ir.mounts.clear();
  return r;
}

// Their navigator, in their units: outputs o in [0, 1] are 0.5 + command / 2.
struct Theirs {
  double x, y, heading_deg, speed = 0, ang_vel = 0;
  void update(double turn_command, double speed_command, double side) {
    ang_vel = std::clamp(ang_vel + (0.5 + turn_command / 2 - 0.5) * 1.0, -3.0, 3.0);
    speed = std::clamp(speed + (0.5 + speed_command / 2 - 0.5) * 1.0, -3.0, 3.0);
    const double vx = std::cos(heading_deg * kDeg) * speed, vy = std::sin(heading_deg * kDeg) * speed;
    heading_deg += ang_vel;
    const double nx = x + vx, ny = y + vy;
    if (std::min({nx, ny, side - nx, side - ny}) >= 8) {   // a square arena's walls
      x = nx;
      y = ny;
    }
  }
};

TEST(AccelerationDrive, MovesAsTheAuthorsNavigatorDoes) {
  // A square arena whose walls the navigator reaches.
  const ArenaSpec arena = test::empty_arena(400 * kUnit, 400 * kUnit);
  World world(arena, navigator());
  Theirs ref{200, 200, 10};
  world.reset({200 * kUnit, 200 * kUnit, 10 * kDeg});
  Rng rng(3);
  int cancelled = 0;
  for (int step = 0; step < 300; ++step) {
    const double turn = step < 150 ? rng.uniform(-0.3, 0.3) : rng.uniform(-1.0, 1.0);
    const double speed = rng.uniform(-0.2, 1.0);
    ref.update(turn, speed, 400);
    world.step(turn, speed);
    const Pose& p = world.state().pose;
    ASSERT_NEAR(p.x_m / kUnit, ref.x, 1e-9) << step;
    ASSERT_NEAR(p.y_m / kUnit, ref.y, 1e-9) << step;
    ASSERT_NEAR(std::remainder(p.heading_rad / kDeg - ref.heading_deg, 360.0), 0.0, 1e-9) << step;
    if (world.state().collided) ++cancelled;
    EXPECT_GE(std::min({p.x_m, p.y_m, arena.width_m - p.x_m, arena.height_m - p.y_m}) / kUnit, 8 - 1e-9);
  }
  EXPECT_GT(cancelled, 0);   // it met the wall
}

TEST(AccelerationDrive, SpeedsRiseToTheirTopsAndTheActuatorsReadThem) {
  World world(test::empty_arena(2.0, 2.0), navigator());
  world.reset({0.2, 1.0, 0.0});
  world.step(1.0, 1.0);
  EXPECT_NEAR(world.state().wheel_speed_mps[0], 0.5 * kDeg / 0.1, 1e-15);   // turn rate, rad/s
  EXPECT_NEAR(world.state().wheel_speed_mps[1], 0.5 * kUnit / 0.1, 1e-15);  // speed, m/s
  for (int i = 0; i < 10; ++i) world.step(1.0, 1.0);
  EXPECT_DOUBLE_EQ(world.state().wheel_speed_mps[0], 3 * kDeg / 0.1);
  EXPECT_DOUBLE_EQ(world.state().wheel_speed_mps[1], 3 * kUnit / 0.1);
  world.step(std::nan(""), -1.0);   // NaN counts as 0
  EXPECT_DOUBLE_EQ(world.state().wheel_speed_mps[0], 3 * kDeg / 0.1);
  EXPECT_NEAR(world.state().wheel_speed_mps[1], 2.5 * kUnit / 0.1, 1e-15);
}

TEST(AccelerationDrive, ReadsNoIrWithoutSensors) {
  World world(test::empty_arena(0.2, 0.2), navigator());
  world.reset({0.05, 0.1, std::numbers::pi});
  std::array<double, kIrSensors> ir;
  ir.fill(7.0);
  Rng rng(1);
  world.read_ir(ir, rng);
  for (const double v : ir) EXPECT_EQ(v, 0.0);
}

}  // namespace
}  // namespace esc::sim
