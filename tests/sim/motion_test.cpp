// Wheel speeds to body motion: straight runs, reversals under inertia, turning in place.
#include <gtest/gtest.h>

#include <cmath>

#include "sim_test_util.hpp"

namespace esc::sim {
namespace {

using test::empty_arena;
using test::robot_with_inertia;

TEST(SimMotion, StraightRunWithoutInertiaCoversCommandedDistance) {
  const RobotParams robot = robot_with_inertia(false);
  World world(empty_arena(2.0, 2.0), robot);
  world.reset({0.1, 1.0, 0.0});
  const int steps = 100;
  for (int i = 0; i < steps; ++i) {
    world.step(1.0, 1.0);
    EXPECT_NEAR(world.state().displacement_m, robot.control_step_s * robot.motor.max_speed_mps, 1e-8);
    EXPECT_NEAR(world.state().forward_displacement_m, world.state().displacement_m, 1e-12);
    EXPECT_EQ(world.state().wheel_speed_mps[0], robot.motor.max_speed_mps);
    EXPECT_FALSE(world.state().collided);
  }
  const double expected = steps * robot.control_step_s * robot.motor.max_speed_mps;  // 0.8 m
  EXPECT_NEAR(world.state().pose.x_m - 0.1, expected, 1e-6 * expected);
  EXPECT_NEAR(world.state().pose.y_m, 1.0, 1e-7);
  EXPECT_NEAR(world.state().pose.heading_rad, 0.0, 1e-7);
}

TEST(SimMotion, StraightRunWithInertiaFollowsTheLagIntegral) {
  const RobotParams robot = robot_with_inertia(true);
  const double dt = robot.control_step_s / robot.physics_substeps;
  const double vmax = robot.motor.max_speed_mps;
  const double a = std::exp(-dt / robot.motor.time_constant_s);
  // From rest the lag's first step is the largest; below the acceleration limit it never binds.
  ASSERT_LE(vmax * (1 - a), robot.motor.max_accel_mps2 * dt);
  World world(empty_arena(2.0, 2.0), robot);
  world.reset({0.1, 1.0, 0.0});
  const int steps = 20;
  for (int i = 0; i < steps; ++i) world.step(1.0, 1.0);
  // Speed after substep k is vmax (1 - a^k); the body holds it for that substep, so the
  // distance is vmax dt sum_{k=1..n} (1 - a^k) = vmax dt (n - a (1 - a^n) / (1 - a)).
  const int n = steps * robot.physics_substeps;
  const double expected = vmax * dt * (n - a * (1 - std::pow(a, n)) / (1 - a));
  EXPECT_NEAR(world.state().pose.x_m - 0.1, expected, 1e-6 * expected);
  EXPECT_NEAR(world.state().wheel_speed_mps[0], vmax * (1 - std::pow(a, n)), 1e-12);
  // And it stays within one substep's travel of the continuous-time lag.
  const double t = steps * robot.control_step_s;
  const double tau = robot.motor.time_constant_s;
  const double continuous = vmax * (t - tau * (1 - std::exp(-t / tau)));
  EXPECT_NEAR(world.state().pose.x_m - 0.1, continuous, vmax * dt);
  EXPECT_LT(world.state().pose.x_m - 0.1, steps * robot.control_step_s * vmax);
}

TEST(SimMotion, ReversalUnderInertiaTakesThePredictedTime) {
  const RobotParams robot = robot_with_inertia(true);
  const double dt = robot.control_step_s / robot.physics_substeps;
  const double vmax = robot.motor.max_speed_mps;
  const double a = std::exp(-dt / robot.motor.time_constant_s);
  const double max_dv = robot.motor.max_accel_mps2 * dt;
  World world(empty_arena(4.0, 4.0), robot);
  world.reset({1.0, 2.0, 0.0});
  for (int i = 0; i < 100; ++i) world.step(1.0, 1.0);  // full speed: gap e^-100 of vmax
  ASSERT_NEAR(world.state().wheel_speed_mps[0], vmax, 1e-15);

  // Prediction: the gap to the target (-vmax) closes by max_dv per substep while the lag
  // step gap (1 - a) exceeds it, then shrinks by a factor a per substep.
  double gap = 2 * vmax;
  int substeps = 0;
  while (gap * (1 - a) > max_dv) {
    gap -= max_dv;
    ++substeps;
  }
  ASSERT_GE(substeps, 1);  // with the defaults the acceleration limit binds at first
  substeps += static_cast<int>(std::ceil(std::log((0.1 * vmax) / gap) / std::log(a)));
  const int predicted_steps = (substeps + robot.physics_substeps - 1) / robot.physics_substeps;
  ASSERT_GE(predicted_steps, 2);

  for (int i = 1; i <= predicted_steps; ++i) {
    world.step(-1.0, -1.0);
    if (i < predicted_steps) {
      EXPECT_GT(world.state().wheel_speed_mps[0], -0.9 * vmax) << "step " << i;
    }
    if (i == 1) {  // still rolling forwards on the whole, slower
      EXPECT_GT(world.state().forward_displacement_m, 0.0);
      // First substep at the acceleration limit, the second on the lag.
      const double v1 = vmax - max_dv;
      const double v2 = -vmax + (v1 + vmax) * a;
      ASSERT_EQ(robot.physics_substeps, 2);
      EXPECT_NEAR(world.state().wheel_speed_mps[1], v2, 1e-12);
      EXPECT_NEAR(world.state().forward_displacement_m, (v1 + v2) * dt, 1e-9);
    }
  }
  EXPECT_LE(world.state().wheel_speed_mps[0], -0.9 * vmax);
  EXPECT_LE(world.state().wheel_speed_mps[1], -0.9 * vmax);
}

TEST(SimMotion, ReversalWithoutInertiaIsImmediate) {
  const RobotParams robot = robot_with_inertia(false);
  World world(empty_arena(4.0, 4.0), robot);
  world.reset({1.0, 2.0, 0.0});
  for (int i = 0; i < 5; ++i) world.step(1.0, 1.0);
  world.step(-1.0, -1.0);
  EXPECT_EQ(world.state().wheel_speed_mps[0], -robot.motor.max_speed_mps);
  EXPECT_NEAR(world.state().forward_displacement_m,
              -robot.motor.max_speed_mps * robot.control_step_s, 1e-8);
}

TEST(SimMotion, CommandsAreClampedAndNanIsStop) {
  const RobotParams robot = robot_with_inertia(false);
  World world(empty_arena(4.0, 4.0), robot);
  world.reset({1.0, 2.0, 0.0});
  world.step(5.0, -7.0);
  EXPECT_EQ(world.state().wheel_speed_mps[0], robot.motor.max_speed_mps);
  EXPECT_EQ(world.state().wheel_speed_mps[1], -robot.motor.max_speed_mps);
  world.step(std::nan(""), 0.0);
  EXPECT_EQ(world.state().wheel_speed_mps[0], 0.0);
}

TEST(SimMotion, TurningInPlaceRotatesAtTwiceMaxSpeedOverWheelBase) {
  const RobotParams robot = robot_with_inertia(false);
  World world(empty_arena(1.0, 1.0), robot);
  world.reset({0.5, 0.5, 0.3});
  const double rate = 2 * robot.motor.max_speed_mps / robot.wheel_base_m;  // rad/s
  double turned = 0.0;
  double heading = world.state().pose.heading_rad;
  const int steps = 30;  // about 9 rad, more than a full turn
  for (int i = 0; i < steps; ++i) {
    world.step(-1.0, 1.0);
    turned += test::wrap_angle(world.state().pose.heading_rad - heading);
    heading = world.state().pose.heading_rad;
    EXPECT_LT(world.state().displacement_m, 1e-6);
    EXPECT_FALSE(world.state().collided);
  }
  EXPECT_NEAR(turned, rate * steps * robot.control_step_s, 1e-5 * turned);
  EXPECT_NEAR(world.state().pose.x_m, 0.5, 1e-6);
  EXPECT_NEAR(world.state().pose.y_m, 0.5, 1e-6);
}

TEST(SimMotion, ArcRadiusMatchesDifferentialDrive) {
  // Left wheel half speed: v = 0.75 vmax, omega = 0.5 vmax / wheel_base, radius v / omega.
  const RobotParams robot = robot_with_inertia(false);
  World world(empty_arena(2.0, 2.0), robot);
  world.reset({1.0, 0.8, 0.0});
  const double radius = 0.75 * robot.wheel_base_m / 0.5;
  for (int i = 0; i < 50; ++i) {
    world.step(0.5, 1.0);
    const double dx = world.state().pose.x_m - 1.0;
    const double dy = world.state().pose.y_m - (0.8 + radius);
    // Each substep moves the body along the exact chord of its arc: no drift off the circle.
    EXPECT_NEAR(std::hypot(dx, dy), radius, 1e-5 * radius);
  }
}

}  // namespace
}  // namespace esc::sim
