// Random start poses clear every wall and obstacle; a full arena is an error.
#include <gtest/gtest.h>

#include <numbers>
#include <stdexcept>

#include "sim_test_util.hpp"

namespace esc::sim {
namespace {

TEST(SimFreePose, NeverOverlapsAnObstacle) {
  ArenaSpec arena = test::empty_arena(0.6, 0.4);
  arena.cylinders.push_back({{0.2, 0.2}, 0.05});
  arena.cylinders.push_back({{0.5, 0.1}, 0.03});
  arena.boxes.push_back({{0.4, 0.3}, {0.15, 0.03}, 0.5});
  arena.boxes.push_back({{0.1, 0.35}, {0.05, 0.05}, -1.2});
  const RobotParams robot;
  World world(arena, robot);
  Rng rng(123);
  const double margin = 0.005;
  double sum_x = 0.0, sum_h = 0.0;
  const int draws = 20000;
  for (int i = 0; i < draws; ++i) {
    const Pose p = world.random_free_pose(rng, margin);
    ASSERT_GE(test::clearance(arena, p.x_m, p.y_m), robot.body_radius_m + margin - 1e-12)
        << p.x_m << ", " << p.y_m;
    ASSERT_GE(p.heading_rad, -std::numbers::pi);
    ASSERT_LT(p.heading_rad, std::numbers::pi);
    sum_x += p.x_m;
    sum_h += p.heading_rad;
  }
  EXPECT_NEAR(sum_h / draws, 0.0, 0.05);
  EXPECT_GT(sum_x / draws, 0.2);
  EXPECT_LT(sum_x / draws, 0.4);
  // A free pose starts without contact.
  world.reset(world.random_free_pose(rng, margin));
  world.step(0.0, 0.0);
  EXPECT_FALSE(world.state().collided);
}

TEST(SimFreePose, SameSeedSamePose) {
  World world(test::empty_arena(0.6, 0.6), RobotParams{});
  Rng a(9), b(9);
  for (int i = 0; i < 10; ++i) {
    const Pose p = world.random_free_pose(a);
    const Pose q = world.random_free_pose(b);
    EXPECT_EQ(p.x_m, q.x_m);
    EXPECT_EQ(p.y_m, q.y_m);
    EXPECT_EQ(p.heading_rad, q.heading_rad);
  }
}

TEST(SimFreePose, ThrowsWhenTheArenaIsFull) {
  ArenaSpec full = test::empty_arena(0.6, 0.6);
  full.boxes.push_back({{0.3, 0.3}, {0.58, 0.58}, 0.0});
  World world(full, RobotParams{});
  Rng rng(1);
  EXPECT_THROW((void)world.random_free_pose(rng), std::runtime_error);

  World tiny(test::empty_arena(0.05, 0.05), RobotParams{});  // narrower than the body
  EXPECT_THROW((void)tiny.random_free_pose(rng), std::runtime_error);
  try {
    (void)tiny.random_free_pose(rng);
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no free space"), std::string::npos);
  }
}

}  // namespace
}  // namespace esc::sim
