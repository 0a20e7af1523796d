// The maze navigator's world (Lehman & Stanley 2011): segment walls in the 2D geometry and in
// Bullet, the rangefinders, the goal radars, and their rules. Expected distances are worked
// out by hand in the comments.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "runtime/sim/geometry2d.hpp"
#include "runtime/sim/goal_radar.hpp"
#include "runtime/sim/validate.hpp"
#include "sim_test_util.hpp"

namespace esc::sim {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// One ray's first hit, up to max_t.
double cast(const StaticGeometry2D& g, Vec2 o, Vec2 d, double max_t = 10.0) {
  double t = max_t;
  g.cast_rays(o, max_t, 1, &o.x, &o.y, &d.x, &d.y, &t);
  return t;
}

std::vector<Rule> rules_of(const std::vector<Problem>& problems) {
  std::vector<Rule> out;
  for (const Problem& p : problems) out.push_back(p.rule);
  return out;
}

TEST(SimNavigation, WallBoxIsTheSegmentsRectangle) {
  const BoxObstacle b = wall_box({{0.3, 0.3}, {0.7, 0.7}, 0.02});
  EXPECT_DOUBLE_EQ(b.center_m.x, 0.5);
  EXPECT_DOUBLE_EQ(b.center_m.y, 0.5);
  EXPECT_DOUBLE_EQ(b.size_m.x, 0.4 * std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(b.size_m.y, 0.02);
  EXPECT_DOUBLE_EQ(b.angle_rad, std::numbers::pi / 4);
}

TEST(SimNavigation, RaysMeetSegmentWallsBoxesCylindersAndTheArenaWalls) {
  ArenaSpec a = test::empty_arena(1.0, 1.0);
  a.walls.push_back({{0.2, 0.6}, {0.8, 0.6}, 0.01});   // faces at y = 0.595 and 0.605
  const StaticGeometry2D g(a);
  EXPECT_NEAR(cast(g, {0.5, 0.3}, {0, 1}), 0.295, 1e-12);          // up to the near face
  EXPECT_NEAR(cast(g, {0.5, 0.9}, {0, -1}), 0.295, 1e-12);         // down to the far face
  EXPECT_NEAR(cast(g, {0.5, 0.3}, {1, 0}), 0.5, 1e-12);            // the right arena wall
  EXPECT_NEAR(cast(g, {0.9, 0.3}, {0, 1}), 0.7, 1e-12);            // past the wall's end, to the top
  EXPECT_NEAR(cast(g, {0.1, 0.6}, {1, 0}), 0.1, 1e-12);            // along it, onto its square end
  // A diagonal wall, y = x from (0.3, 0.3) to (0.7, 0.7), 2 cm thick: a horizontal ray from
  // (0.8, 0.5) meets its centre line at x = 0.5 and its near face 0.01 / sin 45deg sooner.
  ArenaSpec d = test::empty_arena(1.0, 1.0);
  d.walls.push_back({{0.3, 0.3}, {0.7, 0.7}, 0.02});
  EXPECT_NEAR(cast(StaticGeometry2D(d), {0.8, 0.5}, {-1, 0}), 0.3 - 0.01 * std::sqrt(2.0), 1e-12);
  // A block 20 x 10 cm at the centre and a cylinder of radius 10 cm: a ray 5 cm off the
  // cylinder's axis meets it sqrt(0.1^2 - 0.05^2) before the centre's height.
  ArenaSpec b = test::empty_arena(1.0, 1.0);
  b.boxes.push_back({{0.5, 0.5}, {0.2, 0.1}, 0.0});
  EXPECT_NEAR(cast(StaticGeometry2D(b), {0.1, 0.5}, {1, 0}), 0.3, 1e-12);
  ArenaSpec c = test::empty_arena(1.0, 1.0);
  c.cylinders.push_back({{0.5, 0.5}, 0.1});
  EXPECT_NEAR(cast(StaticGeometry2D(c), {0.45, 0.1}, {0, 1}), 0.4 - std::sqrt(0.0075), 1e-12);
}

// cast_fan's culls (the box's own distance, the ray's line passing it, the box behind the
// origin or beyond t) skip only what cannot lower a ray: its readings equal testing every
// shape, bit for bit, also for rays aimed at the boxes' corners and along their faces, where
// a ray grazes a box within rounding.
TEST(SimNavigation, FanCullsGiveTheReadingsOfTestingEveryShape) {
  ArenaSpec a = test::empty_arena(1.0, 0.6);
  Rng rng(7);
  for (int i = 0; i < 12; ++i)  // long thin walls as in a maze, and blocks
    a.walls.push_back({{rng.uniform(0.0, 1.0), rng.uniform(0.0, 0.6)}, {rng.uniform(0.0, 1.0), rng.uniform(0.0, 0.6)},
                       i % 3 == 0 ? 0.05 : 0.002});
  a.boxes.push_back({{0.3, 0.3}, {0.1, 0.04}, 0.0});
  a.cylinders.push_back({{0.7, 0.2}, 0.05});
  const StaticGeometry2D g(a);
  const StaticGeometry2D::Nearby all = g.everything();
  std::vector<BoxObstacle> boxes = a.boxes;
  for (const WallSegment& w : a.walls) boxes.push_back(wall_box(w));
  std::vector<Vec2> corners;  // every wall's and box's corners, where grazing rays are aimed
  for (const BoxObstacle& b : boxes) {
    for (const double sx : {-0.5, 0.5})
      for (const double sy : {-0.5, 0.5}) {
        const double x = sx * b.size_m.x, y = sy * b.size_m.y;
        corners.push_back({b.center_m.x + std::cos(b.angle_rad) * x - std::sin(b.angle_rad) * y,
                           b.center_m.y + std::sin(b.angle_rad) * x + std::cos(b.angle_rad) * y});
      }
  }
  const double range = 0.34375;
  int compared = 0;
  for (int k = 0; k < 20000; ++k) {
    const Vec2 o{rng.uniform(0.01, 0.99), rng.uniform(0.01, 0.59)};
    std::array<double, 6> dx{}, dy{}, t{}, every{};
    for (std::size_t r = 0; r < dx.size(); ++r) {
      double angle = rng.uniform(-std::numbers::pi, std::numbers::pi);
      if (r < 3) {  // at a corner, or passing it by a little more than the culls' margin of 1e-9 m
        const Vec2 c = corners[static_cast<std::size_t>(rng.uniform(0.0, 1.0) * static_cast<double>(corners.size())) %
                               corners.size()];
        const double miss_m = r == 0 ? 0.0 : (r == 1 ? 2e-9 : -3e-9);
        angle = std::atan2(c.y - o.y, c.x - o.x) + miss_m / std::hypot(c.x - o.x, c.y - o.y);
      } else if (r == 3) {  // along a face of a random wall
        angle = wall_box(a.walls[static_cast<std::size_t>(k) % a.walls.size()]).angle_rad;
      }
      dx[r] = std::cos(angle);
      dy[r] = std::sin(angle);
      t[r] = every[r] = range;
    }
    g.cast_fan(all, o, range, 6, dx.data(), dy.data(), t.data());
    const std::array<double, 6> ox{o.x, o.x, o.x, o.x, o.x, o.x}, oy{o.y, o.y, o.y, o.y, o.y, o.y};
    g.cast_rays(o, 1e9, 6, ox.data(), oy.data(), dx.data(), dy.data(), every.data());  // no cull
    for (std::size_t r = 0; r < t.size(); ++r) {
      ASSERT_EQ(std::bit_cast<std::uint64_t>(t[r]), std::bit_cast<std::uint64_t>(every[r]))
          << "ray " << r << " from (" << o.x << ", " << o.y << "): " << t[r] << " against " << every[r];
      compared += every[r] < range;
    }
  }
  EXPECT_GT(compared, 40000);  // most rays meet something within range
}

// The IR sensors and the light sensors' occlusion see a segment wall as the block of its
// rectangle.
TEST(SimNavigation, IrAndLightSeeASegmentWallAsItsRectangle) {
  ArenaSpec walled = test::empty_arena(1.0, 1.0);
  walled.walls.push_back({{0.3, 0.2}, {0.7, 0.6}, 0.02});
  ArenaSpec blocked = test::empty_arena(1.0, 1.0);
  blocked.boxes.push_back(wall_box(walled.walls[0]));
  for (ArenaSpec* a : {&walled, &blocked}) a->lights.push_back({{0.65, 0.2}, 0.0, 1.0, -1});
  World w(walled, RobotParams{});
  World b(blocked, RobotParams{});
  Rng rng(1);
  // Facing the wall, its face 2.25 cm from the body, the light behind it (ahead, to the right).
  const Pose pose{0.5 - 0.06 / std::sqrt(2.0), 0.4 + 0.06 / std::sqrt(2.0), -45 * kDeg};
  w.reset(pose);
  b.reset(pose);
  std::array<double, kIrSensors> ir_w{}, ir_b{};
  w.read_ir(ir_w, rng);
  b.read_ir(ir_b, rng);
  EXPECT_GT(ir_w[2], 0.1);
  EXPECT_EQ(ir_w, ir_b);
  std::array<double, kLightSensors> light_w{}, light_b{};
  w.read_light(light_w, rng);
  b.read_light(light_b, rng);
  EXPECT_EQ(light_w, light_b);
  // Without the wall, the light ahead-right is seen.
  ArenaSpec lit = test::empty_arena(1.0, 1.0);
  lit.lights = walled.lights;
  World seen(lit, RobotParams{});
  seen.reset(pose);
  std::array<double, kLightSensors> light_open{};
  seen.read_light(light_open, rng);
  EXPECT_GT(light_open[3], light_w[3] + 0.1);
}

TEST(SimNavigation, SegmentWallsCountInClearances) {
  ArenaSpec a = test::empty_arena(1.0, 1.0);
  a.walls.push_back({{0.2, 0.6}, {0.8, 0.6}, 0.01});
  const StaticGeometry2D g(a);
  EXPECT_NEAR(g.clearance({0.5, 0.5}), 0.095, 1e-12);
  EXPECT_NEAR(g.obstacle_clearance({0.5, 0.5}), 0.095, 1e-12);   // a wall is an obstacle for zones too
  EXPECT_NEAR(g.obstacle_clearance({0.9, 0.6}), 0.1, 1e-12);     // beyond its end
  EXPECT_NEAR(g.clearance({0.5, 0.6}), -0.005, 1e-12);           // inside it
}

// Rangefinders at 0, 90, -90 and 180 degrees, 40 cm, below a wall 29.5 cm away.
class SimRangefinders : public ::testing::Test {
 protected:
  ArenaSpec arena = test::empty_arena(1.0, 1.0);
  RobotParams robot;

  void SetUp() override {
    arena.walls.push_back({{0.2, 0.6}, {0.8, 0.6}, 0.01});
    robot.rangefinders.angles_rad = {0.0, 90 * kDeg, -90 * kDeg, 180 * kDeg};
    robot.rangefinders.range_m = 0.4;
  }

  std::array<double, kMaxRangefinders> read_at(World& w, Pose p) {
    w.reset(p);
    std::array<double, kMaxRangefinders> out{};
    w.read_rangefinders(out);
    return out;
  }
};

TEST_F(SimRangefinders, ReadDistanceOverRangeRelativeToTheHeading) {
  World w(arena, robot);
  // Facing +y: ahead the wall (0.295), left and right the side walls (0.5, beyond range),
  // behind the bottom wall (0.3).
  auto r = read_at(w, {0.5, 0.3, 90 * kDeg});
  EXPECT_NEAR(r[0], 0.295 / 0.4, 1e-9);
  EXPECT_EQ(r[1], 1.0);
  EXPECT_EQ(r[2], 1.0);
  EXPECT_NEAR(r[3], 0.3 / 0.4, 1e-9);
  for (std::size_t i = 4; i < r.size(); ++i) EXPECT_EQ(r[i], 0.0);   // not written
  // Facing +x, the same walls, a quarter turn round: the wall is to the left (positive angle).
  r = read_at(w, {0.5, 0.3, 0.0});
  EXPECT_EQ(r[0], 1.0);
  EXPECT_NEAR(r[1], 0.295 / 0.4, 1e-9);
  EXPECT_NEAR(r[2], 0.3 / 0.4, 1e-9);
  EXPECT_EQ(r[3], 1.0);
}

TEST_F(SimRangefinders, MeasureFromTheCentreAndReadOneWhenNothingIsInRange) {
  World w(arena, robot);
  // The body touching the wall (its radius from the face): the ray still starts at the centre.
  const double r = robot.body_radius_m;
  EXPECT_NEAR(read_at(w, {0.5, 0.595 - r, 90 * kDeg})[0], r / 0.4, 1e-9);
  // In the open middle of a larger arena, every ray reads 1.
  World open(test::empty_arena(2.0, 2.0), robot);
  for (const double v : read_at(open, {1.0, 1.0, 0.3})) EXPECT_TRUE(v == 1.0 || v == 0.0);
  const auto clear = read_at(open, {1.0, 1.0, 0.3});
  EXPECT_EQ(std::count(clear.begin(), clear.end(), 1.0), 4);
}

TEST(SimRadar, SlicesFrontLeftBackRight) {
  const Vec2 goal{0.9, 0.5};
  // The goal due +x of the robot; as the robot turns left, it passes to the right, behind, left.
  EXPECT_EQ(radar_slice({0.5, 0.5, 0.0}, goal, 4), 0);
  EXPECT_EQ(radar_slice({0.5, 0.5, 90 * kDeg}, goal, 4), 3);
  EXPECT_EQ(radar_slice({0.5, 0.5, 180 * kDeg}, goal, 4), 2);
  EXPECT_EQ(radar_slice({0.5, 0.5, -90 * kDeg}, goal, 4), 1);
  // Each slice is 90 degrees wide about its centre: bearings of 44 and -44 degrees are ahead,
  // 46 degrees is left, -46 right.
  for (const auto& [bearing, slice] : std::vector<std::pair<double, int>>{{44, 0}, {-44, 0}, {46, 1}, {-46, 3},
                                                                         {134, 1}, {136, 2}, {-136, 2}, {-134, 3}})
    EXPECT_EQ(radar_slice({0, 0, 0.3}, {std::cos(0.3 + bearing * kDeg), std::sin(0.3 + bearing * kDeg)}, 4), slice)
        << bearing;
  // Eight slices of 45 degrees: a bearing of 50 degrees is in slice 1 ([22.5, 67.5)).
  EXPECT_EQ(radar_slice({0, 0, 0}, {std::cos(50 * kDeg), std::sin(50 * kDeg)}, 8), 1);
  EXPECT_EQ(radar_slice({0, 0, 0}, {std::cos(-50 * kDeg), std::sin(-50 * kDeg)}, 8), 7);
  // One slice holds everything; a goal at the centre counts as ahead.
  EXPECT_EQ(radar_slice({0, 0, 1.0}, {-1, -1}, 1), 0);
  EXPECT_EQ(radar_slice({0.2, 0.2, 2.0}, {0.2, 0.2}, 4), 0);
}

// GoalRadar decides without atan2 where a bearing is clear of the edges: it must give
// radar_slice's answer everywhere, the edges themselves and bearings a rounding from them
// included (where it hands over to radar_slice).
TEST(SimRadar, GoalRadarAgreesWithRadarSliceEverywhere) {
  std::mt19937_64 gen(12);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int slices = 1; slices <= kMaxRadars; ++slices) {
    const GoalRadar radar(slices);
    const double width = 2 * std::numbers::pi / slices;
    for (int i = 0; i < 20000; ++i) {
      const Pose pose{unit(gen), unit(gen), std::remainder(2 * std::numbers::pi * unit(gen), 2 * std::numbers::pi)};
      const Vec2 facing{std::cos(pose.heading_rad), std::sin(pose.heading_rad)};
      // Half the goals at random, half on an edge, some nudged off it by 1e-16 .. 1e-6 rad.
      double bearing = 2 * std::numbers::pi * unit(gen);
      if (i % 2 == 1) {
        bearing = (static_cast<int>(unit(gen) * slices) - 0.5) * width;
        if (i % 4 == 3) bearing += (unit(gen) < 0.5 ? -1 : 1) * std::pow(10.0, -16 + 10 * unit(gen));
      }
      const double reach = 0.01 + unit(gen);
      const Vec2 goal{pose.x_m + reach * std::cos(pose.heading_rad + bearing),
                      pose.y_m + reach * std::sin(pose.heading_rad + bearing)};
      const int expected = radar_slice(pose, goal, slices);
      ASSERT_EQ(radar.slice(pose, facing, goal), expected) << slices << " slices, bearing " << bearing;
    }
    // The goal at the robot's centre counts as ahead.
    EXPECT_EQ(radar.slice({0.3, 0.3, 1.0}, {std::cos(1.0), std::sin(1.0)}, {0.3, 0.3}), 0);
  }
}

TEST(SimNavigation, ASegmentWallStopsTheRobotDrivenIntoIt) {
  ArenaSpec arena = test::empty_arena(1.0, 1.0);
  arena.walls.push_back({{0.2, 0.6}, {0.8, 0.6}, 0.01});
  const RobotParams robot = test::robot_with_inertia(false);
  World world(arena, robot);
  world.reset({0.5, 0.4, 90 * kDeg});
  const double r = robot.body_radius_m;
  const double stop_y = 0.595 - r;   // the body's rim on the wall's near face
  int first_contact = -1;
  for (int i = 0; i < 60; ++i) {
    world.step(1.0, 1.0);
    const RobotState& s = world.state();
    ASSERT_LE(s.pose.y_m, stop_y + 1e-4) << "passes into the wall at step " << i;
    if (s.collided && first_contact < 0) first_contact = i;
  }
  // 0.195 - r to go at 8 mm per step: contact after about 21 steps.
  EXPECT_NEAR(first_contact, (0.195 - r) / (robot.motor.max_speed_mps * robot.control_step_s), 2.0);
  EXPECT_TRUE(world.state().collided);
  EXPECT_NEAR(world.state().pose.y_m, stop_y, 1e-4);
  EXPECT_NEAR(world.state().pose.x_m, 0.5, 1e-6);
}

TEST(SimNavigation, RandomStartsAndZonesKeepClearOfSegmentWalls) {
  ArenaSpec arena = test::empty_arena(0.6, 0.6);
  arena.walls.push_back({{0.0, 0.3}, {0.45, 0.3}, 0.01});
  arena.walls.push_back({{0.3, 0.6}, {0.3, 0.35}, 0.02});
  arena.walls.push_back({{0.1, 0.1}, {0.5, 0.2}, 0.01});
  Zone z;
  z.radius_m = 0.04;
  z.random_position = true;
  arena.zones.push_back(z);
  const RobotParams robot;
  World world(arena, robot);
  Rng rng(5);
  int near_a_wall = 0;
  for (int i = 0; i < 5000; ++i) {
    const Pose p = world.random_free_pose(rng, 0.0);
    const double clear = test::obstacle_clearance(arena, p.x_m, p.y_m);
    ASSERT_GE(clear, robot.body_radius_m - 1e-12) << p.x_m << ", " << p.y_m;
    near_a_wall += clear < robot.body_radius_m + 0.01 ? 1 : 0;
  }
  EXPECT_GT(near_a_wall, 0);   // the walls are met, not avoided by a wide margin
  for (int i = 0; i < 500; ++i) {
    world.place_zones(rng);
    const Vec2 c = world.zone_centers()[0];
    ASSERT_GE(test::obstacle_clearance(arena, c.x, c.y), z.radius_m - 1e-12) << c.x << ", " << c.y;
  }
}

TEST(SimNavigation, RulesOfWallsGoalAndSensors) {
  ArenaSpec a = test::empty_arena(1.0, 1.0);
  a.walls.push_back({{0.2, 0.2}, {0.2, 0.2}, 0.01});    // no length
  a.walls.push_back({{0.2, 0.2}, {0.5, 0.2}, 0.0});     // no thickness
  a.walls.push_back({{0.5, 0.5}, {1.2, 0.5}, 0.01});    // 20 cm beyond the right wall
  a.goal = Vec2{0.5, 1.1};                              // 10 cm beyond the top wall
  const auto problems = arena_problems(a);
  EXPECT_EQ(rules_of(problems), (std::vector<Rule>{Rule::WallLength, Rule::WallThickness, Rule::WallInside,
                                                   Rule::GoalInside}));
  EXPECT_EQ(problems[0].index, 0);
  EXPECT_EQ(problems[1].index, 1);
  EXPECT_EQ(problems[2].index, 2);
  EXPECT_NEAR(problems[2].found, 0.2, 1e-12);
  EXPECT_NEAR(problems[3].found, 0.1, 1e-12);
  // A wall's thickness reaches past the walls too: 5 mm of a 1 cm wall along the bottom.
  ArenaSpec edge = test::empty_arena(1.0, 1.0);
  edge.walls.push_back({{0.2, 0.0}, {0.5, 0.0}, 0.01});
  ASSERT_EQ(arena_problems(edge).size(), 1U);
  EXPECT_NEAR(arena_problems(edge)[0].found, 0.005, 1e-12);
  // A fixed start on a wall.
  ArenaSpec start = test::empty_arena(1.0, 1.0);
  start.walls.push_back({{0.2, 0.5}, {0.8, 0.5}, 0.01});
  start.fixed_start = Pose{0.5, 0.52, 0.0};
  EXPECT_EQ(rules_of(placement_problems(start, RobotParams{})), std::vector<Rule>{Rule::StartClearOfWall});
  start.fixed_start = Pose{0.5, 0.54, 0.0};   // 3.5 cm from the face: clear of the 2.75 cm body
  EXPECT_TRUE(placement_problems(start, RobotParams{}).empty());
  // Sensors: at most 8 rangefinders, a range above 0, 0 .. 8 radar slices.
  RobotParams r;
  r.rangefinders.angles_rad.assign(9, 0.0);
  r.rangefinders.range_m = 0.0;
  r.radars = 9;
  EXPECT_EQ(rules_of(robot_problems(r)),
            (std::vector<Rule>{Rule::RangefinderCount, Rule::RangefinderRange, Rule::RadarsMax}));
  r = RobotParams{};
  r.radars = -1;
  EXPECT_EQ(rules_of(robot_problems(r)), std::vector<Rule>{Rule::RadarsMin});
  r.radars = 8;
  r.rangefinders.angles_rad.assign(8, 0.0);
  EXPECT_TRUE(robot_problems(r).empty());
}

}  // namespace
}  // namespace esc::sim
