// Bodies of any convex outline (the Thymio II's): the outline's geometry, its distance to the
// arena checked against a sampled boundary, and the Bullet hull stopping at walls where the
// outline meets them, not where the circle around it would.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "runtime/core/rng.hpp"
#include "runtime/sim/geometry2d.hpp"
#include "runtime/sim/outline.hpp"
#include "runtime/sim/validate.hpp"
#include "sim_test_util.hpp"

namespace esc::sim {
namespace {

constexpr double kContactTol = 1e-4;

using test::thymio_like;
using test::thymio_outline;

// Whether p lies inside a convex counter-clockwise polygon.
bool holds(const std::vector<Vec2>& poly, Vec2 p) {
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vec2 a = poly[i], b = poly[(i + 1) % poly.size()];
    if ((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x) < 0) return false;
  }
  return true;
}

// The outline's distance to the arena, from points along its edges (written apart from
// the library's polygon tests): within the sampling step of the exact value; -1 when the
// body holds an obstacle whole (its centre inside the outline).
double sampled_clearance(const ArenaSpec& arena, const std::vector<Vec2>& placed) {
  for (const auto& c : arena.cylinders)
    if (holds(placed, c.center_m)) return -1;
  for (const auto& b : arena.boxes)
    if (holds(placed, b.center_m)) return -1;
  for (const auto& w : arena.walls)
    if (holds(placed, {(w.from_m.x + w.to_m.x) / 2, (w.from_m.y + w.to_m.y) / 2})) return -1;
  double best = 1e9;
  constexpr int kPerEdge = 400;
  for (std::size_t i = 0; i < placed.size(); ++i) {
    const Vec2 a = placed[i], b = placed[(i + 1) % placed.size()];
    for (int k = 0; k < kPerEdge; ++k) {
      const double t = static_cast<double>(k) / kPerEdge;
      const double x = a.x + t * (b.x - a.x), y = a.y + t * (b.y - a.y);
      best = std::min({best, test::clearance(arena, x, y)});
    }
  }
  return best;
}

std::vector<Vec2> placed(const std::vector<Vec2>& outline, const Pose& p) {
  std::vector<Vec2> out(outline.size());
  place_points(outline, p, out);
  return out;
}

TEST(SimOutline, TurnsDepthAndDirection) {
  const std::vector<Vec2> square = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  int at = -1;
  EXPECT_NEAR(smallest_turn(square, at), 1.0, 1e-12);   // right angles: sine 1
  std::vector<Vec2> clockwise(square.rbegin(), square.rend());
  EXPECT_NEAR(smallest_turn(clockwise, at), 1.0, 1e-12);
  EXPECT_LT(twice_signed_area(clockwise), 0.0);
  EXPECT_GT(twice_signed_area(counter_clockwise(clockwise)), 0.0);
  EXPECT_NEAR(origin_depth(square), 1.0, 1e-12);
  const std::vector<Vec2> shifted = {{2, -1}, {4, -1}, {4, 1}, {2, 1}};
  EXPECT_NEAR(origin_depth(shifted), -2.0, 1e-12);
  // A dent at vertex 2.
  const std::vector<Vec2> dented = {{-1, -1}, {1, -1}, {0, 0}, {1, 1}, {-1, 1}};
  EXPECT_LT(smallest_turn(dented, at), 0.0);
  EXPECT_EQ(at, 2);
  // A pentagram turns the same way at every vertex, round twice.
  std::vector<Vec2> star;
  for (int i = 0; i < 5; ++i) {
    const double t = 2 * std::numbers::pi * (2 * i % 5) / 5;
    star.push_back({std::cos(t), std::sin(t)});
  }
  EXPECT_LE(smallest_turn(star, at), 0.0);
}

TEST(SimOutline, InsetEdgesLieTheMarginInside) {
  const std::vector<Vec2> outline = thymio_outline();
  const std::vector<Vec2> in = inset(outline, 0.0005);
  ASSERT_EQ(in.size(), outline.size());
  for (std::size_t i = 0; i < in.size(); ++i) {
    // Each inset edge runs parallel to its edge, 0.5 mm to its left.
    const Vec2 a = outline[i], b = outline[(i + 1) % outline.size()];
    const double len = std::hypot(b.x - a.x, b.y - a.y);
    for (const Vec2& p : {in[i], in[(i + 1) % in.size()]}) {
      const double left = ((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x)) / len;
      EXPECT_NEAR(left, 0.0005, 1e-12) << "edge " << i;
    }
  }
}

TEST(SimOutline, PolarMomentOfASquareAndADisc) {
  // A square of side 2 about its centre: (a^2 + b^2) / 12 with a = b = 2.
  const std::vector<Vec2> square = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  EXPECT_NEAR(polar_gyration_sq(square), 8.0 / 12.0, 1e-12);
  // The same square about a corner: parallel axes add the distance squared, 2.
  const std::vector<Vec2> corner = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  EXPECT_NEAR(polar_gyration_sq(corner), 8.0 / 12.0 + 2.0, 1e-12);
  // A 720-gon tends to the disc's r^2 / 2.
  std::vector<Vec2> disc;
  for (int i = 0; i < 720; ++i) disc.push_back({std::cos(i * std::numbers::pi / 360), std::sin(i * std::numbers::pi / 360)});
  EXPECT_NEAR(polar_gyration_sq(disc), 0.5, 1e-4);
}

TEST(SimOutline, PolygonClearanceMatchesTheSampledBoundary) {
  ArenaSpec arena = test::empty_arena(0.6, 0.5);
  arena.cylinders.push_back({{0.2, 0.35}, 0.04});
  arena.boxes.push_back({{0.42, 0.16}, {0.12, 0.05}, 0.6});
  arena.walls.push_back({{0.05, 0.1}, {0.2, 0.12}, 0.01});
  const StaticGeometry2D geometry(arena);
  const std::vector<Vec2> outline = thymio_outline();
  Rng rng(3);
  int apart = 0, meeting = 0;
  for (int i = 0; i < 2000; ++i) {
    const Pose p{rng.uniform(0.0, 0.6), rng.uniform(0.0, 0.5), rng.uniform(-3.2, 3.2)};
    const std::vector<Vec2> world = placed(outline, p);
    const double exact = geometry.clearance(world);
    const double sampled = sampled_clearance(arena, world);
    if (sampled > 1e-3) {
      // Apart: the sampled boundary is never nearer, and at most a sampling step farther.
      EXPECT_NEAR(exact, sampled, 3e-4) << "pose " << p.x_m << ' ' << p.y_m << ' ' << p.heading_rad;
      ++apart;
    } else if (sampled < -1e-3) {
      EXPECT_LE(exact, 0.0);
      ++meeting;
    }
  }
  EXPECT_GT(apart, 300);
  EXPECT_GT(meeting, 300);
}

TEST(SimOutline, AThinWallAcrossTheBodyMeetsIt) {
  // No vertex of either shape lies inside the other: only the edges cross.
  ArenaSpec arena = test::empty_arena(1.0, 1.0);
  arena.walls.push_back({{0.5, 0.3}, {0.5, 0.7}, 0.002});
  const StaticGeometry2D geometry(arena);
  const std::vector<Vec2> body = placed(thymio_outline(), {0.5, 0.5, 0.0});
  EXPECT_LE(geometry.clearance(body), 0.0);
}

// Straight on into the right wall, forward and in reverse: the hull stops where the outline
// meets the wall, 8 cm ahead of the axle and 3 cm behind it.
TEST(SimOutline, TheHullStopsWhereTheOutlineMeetsTheWall) {
  const RobotParams robot = thymio_like();
  const ArenaSpec arena = test::empty_arena(0.6, 0.6);
  for (const double command : {1.0, -1.0}) {
    World world(arena, robot);
    const double heading = command > 0 ? 0.0 : std::numbers::pi;   // the wall ahead of the move
    world.reset({0.3, 0.3, heading});
    const double reach = command > 0 ? 0.08 : 0.03;   // the outline's reach towards the wall
    bool collided = false;
    for (int i = 0; i < 60; ++i) {
      world.step(command, command);
      const RobotState& s = world.state();
      EXPECT_LE(s.pose.x_m, 0.6 - reach + kContactTol) << "penetrates at step " << i;
      collided = collided || s.collided;
    }
    EXPECT_TRUE(collided);
    EXPECT_TRUE(world.state().collided);
    EXPECT_NEAR(world.state().pose.x_m, 0.6 - reach, 1e-3) << "command " << command;
  }
}

TEST(SimOutline, RandomDrivesNeverPenetrateAndReportTheirContacts) {
  ArenaSpec arena = test::empty_arena(0.8, 0.8);
  arena.cylinders.push_back({{0.4, 0.6}, 0.04});
  arena.boxes.push_back({{0.2, 0.2}, {0.15, 0.06}, 0.6});
  const RobotParams robot = thymio_like();
  const StaticGeometry2D geometry(arena);
  World world(arena, robot);
  Rng rng(5);
  int collisions = 0;
  double deepest = 0.0;
  for (int episode = 0; episode < 30; ++episode) {
    world.reset(world.random_free_pose(rng));
    const double l = rng.uniform(-1.0, 1.0);
    const double r = rng.uniform(-1.0, 1.0);
    for (int i = 0; i < 150; ++i) {
      world.step(l, r);
      const RobotState& s = world.state();
      const double clear = geometry.clearance(placed(robot.outline, s.pose));
      deepest = std::min(deepest, clear);
      if (clear > robot.motor.max_speed_mps * robot.control_step_s + kContactTol) {
        EXPECT_FALSE(s.collided);
      }
      collisions += s.collided ? 1 : 0;
    }
  }
  EXPECT_GT(collisions, 100);
  // As deep as the Khepera's disc sinks (collision_test.cpp), with 6 substeps: the rim moves
  // 4.7 mm a substep when the body spins, the Khepera's 4.2 mm. (With 3 it sank 1.5 mm.)
  EXPECT_GE(deepest, -5e-4);
}

TEST(SimOutline, RulesRefuseWhatIsNoBody) {
  const auto first_rule = [](const RobotParams& r) {
    const auto problems = robot_problems(r);
    return problems.empty() ? std::string("none") : std::string(problems.front().message());
  };
  RobotParams r = thymio_like();
  EXPECT_EQ(first_rule(r), "none");
  r.outline = {{0.01, 0}, {0, 0.01}};
  EXPECT_NE(first_rule(r).find("robot.outline vertex count must be at least 3"), std::string::npos) << first_rule(r);
  r.outline = {{-0.01, -0.01}, {0.01, -0.01}, {0.0, 0.0}, {0.01, 0.01}, {-0.01, 0.01}};
  EXPECT_NE(first_rule(r).find("robot.outline[2]"), std::string::npos) << first_rule(r);
  r.outline = {{0.01, -0.01}, {0.03, -0.01}, {0.03, 0.01}, {0.01, 0.01}};
  EXPECT_NE(first_rule(r).find("inside the body"), std::string::npos) << first_rule(r);
  r.outline = thymio_outline();
  for (Vec2& v : r.outline) v = {1.1 * v.x, 1.1 * v.y};   // the arc beyond the 8 cm circle
  EXPECT_NE(first_rule(r).find("robot.outline[1] distance from the centre"), std::string::npos) << first_rule(r);
  r = thymio_like();
  r.drive = DriveKind::Acceleration;
  EXPECT_NE(first_rule(r).find("under the acceleration drive"), std::string::npos) << first_rule(r);
}

}  // namespace
}  // namespace esc::sim
