// Contacts: the body stops at walls and obstacles, never passes through, and reports it.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sim_test_util.hpp"

namespace esc::sim {
namespace {

constexpr double kContactTol = 1e-4;  // documented in docs/robot-model.md

TEST(SimCollision, DrivingIntoAWallStopsTheBodyAtTheWall) {
  for (bool inertia : {false, true}) {
    const RobotParams robot = test::robot_with_inertia(inertia);
    const ArenaSpec arena = test::empty_arena(0.6, 0.6);
    World world(arena, robot);
    world.reset({0.3, 0.3, 0.0});
    const double r = robot.body_radius_m;
    int first_contact = -1;
    for (int i = 0; i < 60; ++i) {
      world.step(1.0, 1.0);
      const RobotState& s = world.state();
      EXPECT_LE(s.pose.x_m, 0.6 - r + kContactTol) << "penetrates at step " << i;
      if (s.collided && first_contact < 0) first_contact = i;
      if (first_contact < 0) {
        EXPECT_LT(s.pose.x_m, 0.6 - r - kContactTol);
      }
    }
    // 0.3 - r to go at 8 mm per step: contact after about 34 steps.
    const double to_go = 0.3 - r;
    EXPECT_NEAR(first_contact, to_go / (robot.motor.max_speed_mps * robot.control_step_s), 3.0);
    EXPECT_TRUE(world.state().collided);
    EXPECT_NEAR(world.state().pose.x_m, 0.6 - r, kContactTol);
    // Wheels still spinning, body still: about zero displacement.
    world.step(1.0, 1.0);
    EXPECT_LT(world.state().displacement_m, 1e-5);
    EXPECT_TRUE(world.state().collided);
    EXPECT_EQ(world.state().wheel_speed_mps[0], inertia ? world.state().wheel_speed_mps[0]
                                                        : robot.motor.max_speed_mps);
    // Backing off clears the flag.
    for (int i = 0; i < 5; ++i) world.step(-1.0, -1.0);
    EXPECT_FALSE(world.state().collided);
  }
}

TEST(SimCollision, ObliqueAndObstacleContactsNeverPenetrate) {
  ArenaSpec arena = test::empty_arena(0.6, 0.6);
  arena.cylinders.push_back({{0.3, 0.45}, 0.03});
  arena.boxes.push_back({{0.15, 0.15}, {0.12, 0.05}, 0.6});
  const RobotParams robot = test::robot_with_inertia(true);
  World world(arena, robot);
  Rng rng(11);
  int collisions = 0;
  for (int episode = 0; episode < 40; ++episode) {
    world.reset(world.random_free_pose(rng));
    const double l = rng.uniform(0.3, 1.0);
    const double r = rng.uniform(0.3, 1.0);
    for (int i = 0; i < 150; ++i) {
      world.step(l, r);
      const RobotState& s = world.state();
      const double clear = test::clearance(arena, s.pose.x_m, s.pose.y_m) - robot.body_radius_m;
      ASSERT_GE(clear, -5e-4) << "episode " << episode << " step " << i;
      if (clear <= kContactTol) {
        EXPECT_TRUE(s.collided);
      }
      if (clear > robot.motor.max_speed_mps * robot.control_step_s + kContactTol) {
        EXPECT_FALSE(s.collided);
      }
      collisions += s.collided ? 1 : 0;
    }
  }
  EXPECT_GT(collisions, 100);
}

TEST(SimCollision, NoCollisionFarFromEverything) {
  const RobotParams robot = test::robot_with_inertia(true);
  World world(test::empty_arena(0.6, 0.6), robot);
  world.reset({0.3, 0.3, 1.0});
  for (int i = 0; i < 200; ++i) {
    // Forwards, backwards, spin left, spin right: 8 cm out and back, then turns.
    const int phase = (i / 10) % 4;
    const double left[] = {1.0, -1.0, -1.0, 1.0};
    const double right[] = {1.0, -1.0, 1.0, -1.0};
    world.step(left[phase], right[phase]);
    ASSERT_FALSE(world.state().collided) << i;
  }
}

}  // namespace
}  // namespace esc::sim
