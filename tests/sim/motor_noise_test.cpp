// Motor noise (robot.motor.noise_sd, docs/robot-model.md): each wheel pursues its command
// with a Gaussian speed error, a fraction of the command, drawn once per wheel and control
// step from the evaluation's noise stream. Without it nothing is drawn, so every noise-free
// result is what it was; with it the error is unbiased, of the set spread, within the top
// speed, and reproducible from the stream.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "runtime/sim/motor.hpp"
#include "sim_test_util.hpp"

namespace esc::sim {
namespace {

RobotParams robot(double noise_sd) {
  RobotParams r;
  r.motor.inertia = false;   // the wheel speed is the (noisy) target at once
  r.motor.noise_sd = noise_sd;
  return r;
}

TEST(MotorNoise, NoiseFreeMotorsDrawNothing) {
  World world(test::empty_arena(1.0, 1.0), robot(0.0));
  world.reset({0.5, 0.5, 0.0});
  Rng used(7), fresh(7);
  for (int i = 0; i < 20; ++i) world.step(0.5, 0.8, used);
  EXPECT_EQ(used.normal(), fresh.normal());
  EXPECT_DOUBLE_EQ(world.state().wheel_speed_mps[0], 0.5 * robot(0.0).motor.max_speed_mps);
}

TEST(MotorNoise, ErrorIsUnbiasedWithTheSetSpreadAndWithinTheTopSpeed) {
  const RobotParams r = robot(0.1);
  const WheelMotor motor(r.motor, r.control_step_s / r.physics_substeps);
  Rng rng(11);
  const double target = 0.5 * r.motor.max_speed_mps;
  double sum = 0.0, squares = 0.0;
  constexpr int kDraws = 20000;
  for (int i = 0; i < kDraws; ++i) {
    const double v = motor.noisy(target, &rng) / target - 1.0;
    sum += v;
    squares += v * v;
  }
  const double mean = sum / kDraws;
  const double sd = std::sqrt(squares / kDraws - mean * mean);
  EXPECT_NEAR(mean, 0.0, 0.005);   // 5 standard errors
  EXPECT_NEAR(sd, 0.1, 0.005);
  // At full speed the error can only slow the wheel.
  for (int i = 0; i < 1000; ++i) EXPECT_LE(std::abs(motor.noisy(-r.motor.max_speed_mps, &rng)), r.motor.max_speed_mps);
}

TEST(MotorNoise, SameStreamSameTrajectoryOtherStreamAnother) {
  const auto trajectory = [](std::uint64_t seed) {
    World world(test::empty_arena(1.0, 1.0), robot(0.2));
    world.reset({0.5, 0.5, 0.0});
    Rng rng(seed);
    std::vector<double> xs;
    for (int i = 0; i < 50; ++i) {
      world.step(0.6, 0.6, rng);
      xs.push_back(world.state().pose.x_m);
      xs.push_back(world.state().pose.heading_rad);
    }
    return xs;
  };
  EXPECT_EQ(trajectory(3), trajectory(3));
  EXPECT_NE(trajectory(3), trajectory(4));
  // Equal commands, unequal wheels: the robot no longer drives straight.
  EXPECT_NE(trajectory(3).back(), 0.0);
}

TEST(MotorNoise, StepWithoutAStreamIsRefusedForANoisyRobot) {
  World world(test::empty_arena(1.0, 1.0), robot(0.1));
  world.reset({0.5, 0.5, 0.0});
  EXPECT_THROW(world.step(0.5, 0.5), std::logic_error);
}

}  // namespace
}  // namespace esc::sim
