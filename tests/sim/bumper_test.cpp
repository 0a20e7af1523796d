// Bumpers: sectors of the body's edge that read 1 on a step in which the body touched a wall
// or obstacle there, from the point of the walls nearest to the body (a disc, an outline, the
// kinematic navigator's cancelled move).
#include <gtest/gtest.h>

#include <cstdint>
#include <numbers>
#include <vector>

#include "runtime/sim/geometry2d.hpp"
#include "sim_test_util.hpp"

namespace esc::sim {
namespace {

constexpr double kDeg = std::numbers::pi / 180;

TEST(SimBumpers, ASectorHoldsTheBearingsBetweenItsEdgesCounterClockwise) {
  const BumperSector front{-45 * kDeg, 45 * kDeg}, back{135 * kDeg, 225 * kDeg};
  EXPECT_TRUE(front.holds(0.0));
  EXPECT_TRUE(front.holds(44 * kDeg));
  EXPECT_FALSE(front.holds(46 * kDeg));
  EXPECT_TRUE(front.holds(-44 * kDeg + 2 * std::numbers::pi));   // a bearing a turn away
  EXPECT_TRUE(back.holds(std::numbers::pi));
  EXPECT_TRUE(back.holds(-170 * kDeg));
  EXPECT_FALSE(back.holds(0.0));
  EXPECT_TRUE((BumperSector{0.0, 2 * std::numbers::pi}.holds(-3.0)));   // the whole edge
}

TEST(SimBumpers, TheNearestPointOfTheWallsAndObstacles) {
  ArenaSpec arena = test::empty_arena(1.0, 1.0);
  arena.cylinders.push_back({{0.3, 0.7}, 0.05});
  arena.boxes.push_back({{0.7, 0.3}, {0.2, 0.1}, 0.0});
  const StaticGeometry2D g(arena);
  const auto near = [&](Vec2 p, Vec2 want) {
    const Vec2 at = g.nearest_point(p);
    EXPECT_NEAR(at.x, want.x, 1e-12) << p.x << ' ' << p.y;
    EXPECT_NEAR(at.y, want.y, 1e-12) << p.x << ' ' << p.y;
  };
  near({0.02, 0.5}, {0.0, 0.5});               // the left wall
  near({0.3, 0.6}, {0.3, 0.65});               // the cylinder, below it
  near({0.7, 0.2}, {0.7, 0.25});               // the box, below it
  near({0.85, 0.4}, {0.8, 0.35});              // its upper right corner
  near({0.7, 0.33}, {0.7, 0.35});              // inside it: out through the nearer side
  // The box's corner against a polygon's side: the corner, nearer than any of its vertices.
  const std::vector<Vec2> diamond = {{0.85, 0.36}, {0.95, 0.46}, {0.85, 0.56}, {0.75, 0.46}};
  const Vec2 corner = g.nearest_point(diamond);
  EXPECT_NEAR(corner.x, 0.8, 1e-12);
  EXPECT_NEAR(corner.y, 0.35, 1e-12);
  // A side parallel to the box's top, over its middle: the middle of what it faces.
  const std::vector<Vec2> flat = {{0.65, 0.37}, {0.75, 0.37}, {0.75, 0.45}, {0.65, 0.45}};
  const Vec2 middle = g.nearest_point(flat);
  EXPECT_NEAR(middle.x, 0.7, 1e-12);
  EXPECT_NEAR(middle.y, 0.35, 1e-12);
  // Between two walls, in the corner: between them.
  const Vec2 both = g.nearest_point(Vec2{0.03, 0.03});
  EXPECT_NEAR(both.x, 0.015, 1e-12);
  EXPECT_NEAR(both.y, 0.015, 1e-12);
}

// Into the right wall forward, then backing into it: the front bumper, then the back one.
TEST(SimBumpers, TheBumperFacingTheWallReads) {
  for (RobotParams robot : {RobotParams{}, test::thymio_like()}) {
    robot.bumpers = {{-45 * kDeg, 45 * kDeg}, {135 * kDeg, 225 * kDeg}};
    World world(test::empty_arena(0.6, 0.6), robot);
    world.reset({0.3, 0.3, 0.0});
    std::uint32_t seen = 0;
    for (int i = 0; i < 60; ++i) {
      world.step(1.0, 1.0);
      if (!world.state().collided) {
        EXPECT_EQ(world.state().bumped, 0u);
      }
      seen |= world.state().bumped;
    }
    EXPECT_EQ(seen, 1u);
    world.reset({0.3, 0.3, std::numbers::pi});   // facing left, backing to the right
    seen = 0;
    for (int i = 0; i < 60; ++i) {
      world.step(-1.0, -1.0);
      seen |= world.state().bumped;
    }
    EXPECT_EQ(seen, 2u);
  }
}

// The navigator's cancelled move: the bumper facing the wall it would have met.
TEST(SimBumpers, TheNavigatorsCancelledMoveBumps) {
  RobotParams robot;
  robot.drive = DriveKind::Acceleration;
  robot.ir.mounts.clear();
  robot.bumpers = {{-45 * kDeg, 45 * kDeg}, {45 * kDeg, 315 * kDeg}};
  World world(test::empty_arena(0.6, 0.6), robot);
  world.reset({0.3, 0.3, 0.0});
  std::uint32_t seen = 0;
  int collided = 0;
  for (int i = 0; i < 80; ++i) {
    world.step(0.0, 1.0);   // no turn, full speed ahead
    seen |= world.state().bumped;
    collided += world.state().collided ? 1 : 0;
  }
  EXPECT_GT(collided, 0);
  EXPECT_EQ(seen, 1u);
  // Hugging the left wall 1 mm off it, up into the top one: the wall ahead, not the one beside.
  world.reset({robot.body_radius_m + 0.001, 0.3, std::numbers::pi / 2});
  seen = 0;
  for (int i = 0; i < 80; ++i) {
    world.step(0.0, 1.0);
    seen |= world.state().bumped;
  }
  EXPECT_EQ(seen, 1u);
}

}  // namespace
}  // namespace esc::sim
