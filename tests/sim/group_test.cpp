// Several robots in one world (docs/groups.md): they collide through Bullet, their IR sensors
// and rangefinders meet each other's bodies exactly as they meet a cylinder of the same place
// and radius, navigators cannot overlap, random starts keep them apart, and the grid finds
// every robot within a reach.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "runtime/sim/neighbours.hpp"
#include "runtime/sim/world.hpp"
#include "sim_test_util.hpp"

namespace esc::sim {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

double distance(const Pose& a, const Pose& b) { return std::hypot(a.x_m - b.x_m, a.y_m - b.y_m); }

// Lehman & Stanley's navigator (acceleration_drive_test.cpp's) with its six rangefinders.
RobotParams navigator() {
  constexpr double kUnit = 0.0034375;   // metres per maze unit
  RobotParams r;
  r.drive = DriveKind::Acceleration;
  r.body_radius_m = 8 * kUnit;
  r.motor.max_speed_mps = 3 * kUnit / r.control_step_s;
  r.motor.max_accel_mps2 = 0.5 * kUnit / (r.control_step_s * r.control_step_s);
  r.turn.max_rate_radps = 3 * kDeg / r.control_step_s;
  r.turn.max_accel_radps2 = 0.5 * kDeg / (r.control_step_s * r.control_step_s);
  r.ir.mounts.clear();
  r.rangefinders.angles_rad = {-90 * kDeg, -45 * kDeg, 0.0, 45 * kDeg, 90 * kDeg, 180 * kDeg};
  r.rangefinders.range_m = 0.34375;
  return r;
}

TEST(SimGroup, TwoKheperasDrivenHeadOnStopAtContactWithoutPassingThrough) {
  World world(test::empty_arena(1.0, 1.0), std::vector<RobotParams>(2, test::robot_with_inertia(false)));
  const std::array<Pose, 2> starts = {Pose{0.3, 0.5, 0.0}, Pose{0.7, 0.5, std::numbers::pi}};
  world.reset(starts);
  const double radius = world.robot().body_radius_m;
  Rng rng(1);
  const std::array<DriveCommand, 2> ahead = {DriveCommand{1.0, 1.0}, DriveCommand{1.0, 1.0}};
  bool met = false;
  for (int step = 0; step < 200; ++step) {
    world.step(ahead, rng);
    const double apart = distance(world.state(0).pose, world.state(1).pose);
    ASSERT_GT(apart, 2 * radius - 1e-3) << "step " << step;   // Bullet's solver allows a little
    ASSERT_LT(world.state(0).pose.x_m, world.state(1).pose.x_m);
    if (world.state(0).collided) {
      met = true;
      EXPECT_TRUE(world.state(1).collided);
      EXPECT_LT(apart, 2 * radius + 1e-3);
    }
  }
  EXPECT_TRUE(met);
}

TEST(SimGroup, ARobotAloneDrivesAsInItsOwnWorld) {
  // Far apart, two robots integrate alone, as a robot in its own world does, to the bit.
  const RobotParams k = test::robot_with_inertia(true);
  World solo(test::empty_arena(2.0, 1.0), k);
  World pair(test::empty_arena(2.0, 1.0), std::vector<RobotParams>(2, k));
  const Pose start{0.4, 0.5, 0.3};
  solo.reset(start);
  const std::array<Pose, 2> starts = {start, Pose{1.6, 0.5, 0.0}};
  pair.reset(starts);
  Rng a(3), b(3);
  for (int step = 0; step < 40; ++step) {
    const double l = 0.3 + 0.01 * step, r = 0.5;
    solo.step(l, r, a);
    const std::array<DriveCommand, 2> commands = {DriveCommand{l, r}, DriveCommand{0.0, 0.0}};
    pair.step(commands, b);
    ASSERT_EQ(solo.state().pose.x_m, pair.state(0).pose.x_m);
    ASSERT_EQ(solo.state().pose.y_m, pair.state(0).pose.y_m);
    ASSERT_EQ(solo.state().pose.heading_rad, pair.state(0).pose.heading_rad);
  }
}

// Robot 1 stands where a cylinder of its radius would: robot 0's IR reads the same.
// What robot `k` at `p0` alone reads of a cylinder of `radius_m` at `q` (its noise stream Rng(1)).
std::array<double, kIrSensors> ir_beside_cylinder(const RobotParams& k, const Pose& p0, Vec2 q, double radius_m) {
  ArenaSpec with_cylinder = test::empty_arena(1.0, 1.0);
  with_cylinder.cylinders.push_back({q, radius_m});
  World alone(with_cylinder, k);
  alone.reset(p0);
  std::array<double, kIrSensors> expected{};
  Rng rng(1);
  alone.read_ir(expected, rng);
  return expected;
}

TEST(SimGroup, IrSeesAnotherRobotAsACylinderOfItsRadius) {
  const RobotParams k = test::robot_with_inertia(false);
  for (const double gap : {0.005, 0.02, 0.04, 0.2}) {
    for (const double bearing : {0.0, 30 * kDeg, -50 * kDeg, 160 * kDeg}) {
      const Pose p0{0.5, 0.5, 0.2};
      const double d = 2 * k.body_radius_m + gap;
      const Vec2 q{p0.x_m + d * std::cos(p0.heading_rad + bearing), p0.y_m + d * std::sin(p0.heading_rad + bearing)};
      World pair(test::empty_arena(1.0, 1.0), std::vector<RobotParams>(2, k));
      // Robot 1 faces robot 0.
      const std::array<Pose, 2> starts = {p0, Pose{q.x, q.y, p0.heading_rad + bearing + std::numbers::pi}};
      pair.reset(starts);
      std::array<double, kIrSensors> seen{};
      Rng r1(1);
      pair.read_ir(seen, r1);
      EXPECT_EQ(seen, ir_beside_cylinder(k, p0, q, k.body_radius_m)) << "gap " << gap << ", bearing " << bearing;
      if (gap < 0.04 && bearing == 0.0) {
        EXPECT_GT(*std::max_element(seen.begin(), seen.end()), 0.0);
      }
      // And robot 1 sees robot 0 as robot 0 sees it, straight ahead (to rounding: its heading
      // is robot 0's turned by pi).
      if (bearing == 0.0) {
        std::array<double, kIrSensors> back{};
        pair.read_ir(back, r1, 1);
        for (std::size_t s = 0; s < kIrSensors; ++s) EXPECT_NEAR(back[s], seen[s], 1e-12) << "gap " << gap;
      }
    }
  }
}

// A robot's emission is read by the others' light sensors exactly as an arena's light of its
// intensity and height where the robot stands; not by the robot itself.
TEST(SimGroup, ARobotsEmissionIsReadAsAnArenaLightWhereItIs) {
  RobotParams dark = test::robot_with_inertia(false);
  RobotParams lit = dark;
  lit.emission = {0.8, 0.02};
  for (const double bearing : {0.0, 40 * kDeg, -100 * kDeg, 180 * kDeg}) {
    const Pose p0{0.5, 0.5, 0.3};
    const double d = 0.12;
    const Vec2 q{p0.x_m + d * std::cos(p0.heading_rad + bearing), p0.y_m + d * std::sin(p0.heading_rad + bearing)};
    World pair(test::empty_arena(1.0, 1.0), std::vector<RobotParams>{dark, lit});
    const std::array<Pose, 2> starts = {p0, Pose{q.x, q.y, 1.0}};
    pair.reset(starts);
    ArenaSpec with_light = test::empty_arena(1.0, 1.0);
    with_light.lights.push_back({q, 0.02, 0.8, -1});
    World alone(with_light, dark);
    alone.reset(p0);
    std::array<double, kLightSensors> seen{}, expected{}, own{};
    Rng r1(1), r2(1);
    pair.read_light(seen, r1);
    alone.read_light(expected, r2);
    EXPECT_EQ(seen, expected) << "bearing " << bearing;
    EXPECT_GT(*std::max_element(seen.begin(), seen.end()), 0.05) << "bearing " << bearing;
    pair.read_light(own, r1, 1);
    EXPECT_EQ(*std::max_element(own.begin(), own.end()), 0.0) << "a robot does not read its own light";
  }
}

TEST(SimGroup, RangefindersMeetOtherNavigatorsAndNavigatorsDoNotOverlap) {
  const RobotParams nav = navigator();
  World pair(test::empty_arena(2.0, 2.0), std::vector<RobotParams>(2, nav));
  const std::array<Pose, 2> starts = {Pose{0.5, 1.0, 0.0}, Pose{0.7, 1.0, std::numbers::pi}};
  pair.reset(starts);
  ArenaSpec with_cylinder = test::empty_arena(2.0, 2.0);
  with_cylinder.cylinders.push_back({{0.7, 1.0}, nav.body_radius_m});
  World alone(with_cylinder, nav);
  alone.reset(starts[0]);
  std::array<double, 6> seen{}, expected{};
  pair.read_rangefinders(seen);
  alone.read_rangefinders(expected);
  EXPECT_EQ(seen, expected);
  EXPECT_NEAR(seen[2] * nav.rangefinders.range_m, 0.2 - nav.body_radius_m, 1e-12);   // from its centre
  // Full speed at each other: the moves that would overlap are cancelled.
  Rng rng(1);
  const std::array<DriveCommand, 2> ahead = {DriveCommand{0.0, 1.0}, DriveCommand{0.0, 1.0}};
  bool stopped = false;
  for (int step = 0; step < 100; ++step) {
    pair.step(ahead, rng);
    ASSERT_GE(distance(pair.state(0).pose, pair.state(1).pose), 2 * nav.body_radius_m);
    stopped = stopped || pair.state(0).collided;
  }
  EXPECT_TRUE(stopped);
}

TEST(SimGroup, RandomStartsKeepTheRobotsApartAndRobotZeroDrawsAsAlone) {
  ArenaSpec arena = test::empty_arena(1.0, 1.0);
  arena.cylinders.push_back({{0.5, 0.5}, 0.1});
  const RobotParams k = test::robot_with_inertia(false);
  World group(arena, std::vector<RobotParams>(30, k));
  World alone(arena, k);
  Rng a(7), b(7);
  const std::vector<Pose> poses = group.random_free_poses(a, 0.005);
  ASSERT_EQ(poses.size(), 30U);
  const Pose first = alone.random_free_pose(b, 0.005);
  EXPECT_EQ(poses[0].x_m, first.x_m);
  EXPECT_EQ(poses[0].heading_rad, first.heading_rad);
  for (std::size_t i = 0; i < poses.size(); ++i)
    for (std::size_t j = i + 1; j < poses.size(); ++j)
      EXPECT_GE(distance(poses[i], poses[j]), 2 * k.body_radius_m + 0.005) << i << ", " << j;
  // begin_epoch places every robot so.
  Rng c(9);
  group.begin_epoch(c);
  for (std::size_t i = 0; i < 30; ++i)
    for (std::size_t j = i + 1; j < 30; ++j)
      EXPECT_GE(distance(group.state(i).pose, group.state(j).pose), 2 * k.body_radius_m + 0.005);
  // A 7 cm arena holds one Khepera (its centre within 5 mm of the middle), not two: a clear
  // error naming the second.
  try {
    World crowded(test::empty_arena(0.07, 0.07), std::vector<RobotParams>(2, k));
    FAIL() << "two Kheperas fit in 7 cm";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("robot 1"), std::string::npos) << e.what();
  }
}

// Formations (formation.hpp): a line of robots side by side facing one heading, spaced as
// asked; a circle about a centre, each facing out; given poses taken as they are; each drawn
// from the epoch's stream clear of the walls and obstacles; refused where they cannot be taken.
TEST(SimGroup, FormationsPlaceTheGroupAsDeclared) {
  ArenaSpec arena = test::empty_arena(1.0, 1.0);
  arena.cylinders.push_back({{0.5, 0.5}, 0.1});
  const RobotParams k = test::robot_with_inertia(false);
  World group(arena, std::vector<RobotParams>(4, k));
  group.set_formation({FormationKind::Line, 0.1, {}});
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    Rng rng(seed);
    group.begin_epoch(rng);
    const double h = group.state(0).pose.heading_rad;
    for (std::size_t i = 0; i < 4; ++i) {
      const Pose& p = group.state(i).pose;
      EXPECT_EQ(p.heading_rad, h);
      EXPECT_GE(std::hypot(p.x_m - 0.5, p.y_m - 0.5), 0.1 + k.body_radius_m) << "clear of the cylinder";
      if (i == 0) continue;
      const Pose& q = group.state(i - 1).pose;
      EXPECT_NEAR(distance(p, q), 0.1, 1e-12);
      // Side by side: the step from one to the next is perpendicular to the heading.
      EXPECT_NEAR((p.x_m - q.x_m) * std::cos(h) + (p.y_m - q.y_m) * std::sin(h), 0.0, 1e-12);
    }
  }
  group.set_formation({FormationKind::Circle, 0.15, {}});
  Rng rng(3), again(3);
  group.begin_epoch(rng);
  double cx = 0.0, cy = 0.0;
  for (std::size_t i = 0; i < 4; ++i) {
    cx += group.state(i).pose.x_m / 4;
    cy += group.state(i).pose.y_m / 4;
  }
  for (std::size_t i = 0; i < 4; ++i) {
    const Pose& p = group.state(i).pose;
    EXPECT_NEAR(std::hypot(p.x_m - cx, p.y_m - cy), 0.15, 1e-12);
    EXPECT_NEAR(std::remainder(std::atan2(p.y_m - cy, p.x_m - cx) - p.heading_rad, 2 * std::numbers::pi), 0.0, 1e-9)
        << "facing out";
  }
  const Pose first = group.state(2).pose;
  group.begin_epoch(again);
  EXPECT_EQ(group.state(2).pose.x_m, first.x_m) << "drawn from the epoch's stream alone";
  const std::vector<Pose> at = {{0.1, 0.1, 0.0}, {0.2, 0.1, 1.0}, {0.3, 0.1, 2.0}, {0.4, 0.1, 3.0}};
  group.set_formation({FormationKind::At, 0.0, at});
  group.begin_epoch(rng);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(group.state(i).pose.heading_rad, at[i].heading_rad);
  // Refused: overlapping neighbours, a formation wider than the arena, a pose per robot, a
  // pose in the cylinder.
  for (const Formation& bad : {Formation{FormationKind::Line, 0.05, {}}, Formation{FormationKind::Line, 0.4, {}},
                               Formation{FormationKind::At, 0.0, {at.begin(), at.begin() + 3}},
                               Formation{FormationKind::At, 0.0, {{0.1, 0.1, 0}, {0.2, 0.1, 0}, {0.5, 0.5, 0}, {0.4, 0.1, 0}}}})
    EXPECT_THROW(group.set_formation(bad), std::invalid_argument);
}

// The same epoch twice, in a fresh world and in one that ran other epochs before (a worker
// reuses its world): Bullet's world after a reset is a fresh one's, its bodies in the same order.
TEST(SimGroup, ACrowdStepsTheSameInAFreshWorldAndAReusedOne) {
  for (const std::size_t n : {2U, 3U, 4U, 12U}) {
    const RobotParams k = test::robot_with_inertia(true);
    const auto run = [&](World& world, std::uint64_t seed) {
      Rng rng(seed);
      world.begin_epoch(rng);
      std::vector<DriveCommand> commands(n);
      for (int step = 0; step < 300; ++step) {
        for (std::size_t i = 0; i < n; ++i)
          commands[i] = {std::sin(0.1 * step + static_cast<double>(i)), std::cos(0.07 * step - static_cast<double>(i))};
        world.step(commands, rng);
      }
      std::vector<double> out;
      for (std::size_t i = 0; i < n; ++i) {
        out.push_back(world.state(i).pose.x_m);
        out.push_back(world.state(i).pose.y_m);
        out.push_back(world.state(i).pose.heading_rad);
        out.push_back(world.state(i).collided);
      }
      return out;
    };
    const ArenaSpec arena = test::empty_arena(0.3, 0.3);
    World fresh(arena, std::vector<RobotParams>(n, k));
    const std::vector<double> expected = run(fresh, 5);
    World reused(arena, std::vector<RobotParams>(n, k));
    (void)run(reused, 99);
    (void)run(reused, 5);
    (void)run(reused, 17);
    EXPECT_EQ(run(reused, 5), expected) << n << " robots";
  }
}

TEST(SimGroup, ACrowdStepsTheSameTwice) {
  const RobotParams k = test::robot_with_inertia(true);
  const auto run = [&] {
    World world(test::empty_arena(0.6, 0.6), std::vector<RobotParams>(12, k));
    Rng rng(5);
    world.begin_epoch(rng);
    std::vector<DriveCommand> commands(12);
    for (int step = 0; step < 300; ++step) {
      for (std::size_t i = 0; i < commands.size(); ++i)
        commands[i] = {std::sin(0.1 * step + static_cast<double>(i)), std::cos(0.07 * step - static_cast<double>(i))};
      world.step(commands, rng);
    }
    std::vector<double> out;
    int collisions = 0;
    for (std::size_t i = 0; i < 12; ++i) {
      out.push_back(world.state(i).pose.x_m);
      out.push_back(world.state(i).pose.heading_rad);
      collisions += world.state(i).collided;
    }
    out.push_back(collisions);
    return out;
  };
  EXPECT_EQ(run(), run());
}

TEST(SimGroup, BumpersFeelAnotherRobot) {
  RobotParams k = test::robot_with_inertia(false);
  k.bumpers = {{-45 * kDeg, 45 * kDeg}, {135 * kDeg, 225 * kDeg}};
  World world(test::empty_arena(1.0, 1.0), std::vector<RobotParams>(2, k));
  const std::array<Pose, 2> starts = {Pose{0.3, 0.5, 0.0}, Pose{0.3 + 2 * k.body_radius_m + 0.01, 0.5, 0.0}};
  world.reset(starts);
  Rng rng(1);
  const std::array<DriveCommand, 2> commands = {DriveCommand{1.0, 1.0}, DriveCommand{0.0, 0.0}};
  std::uint32_t front = 0, back = 0;
  for (int step = 0; step < 20; ++step) {
    world.step(commands, rng);
    front |= world.state(0).bumped;
    back |= world.state(1).bumped;
  }
  EXPECT_EQ(front, 1U);   // robot 0's front bumper
  EXPECT_EQ(back, 2U);    // robot 1's back bumper
}

// A Khepera of top speed `speed_mps`, stepped in 10 substeps.
RobotParams at_top_speed(double speed_mps) {
  RobotParams r = test::robot_with_inertia(false);
  r.motor.max_speed_mps = speed_mps;
  r.physics_substeps = 10;
  return r;
}

// A fast robot with a higher index than a slow one, driving at it: the pair is found from
// either end (the grid is searched with the fastest robot's travel).
TEST(SimGroup, RobotsOfDifferentSpeedsStopAtContact) {
  const RobotParams slow = at_top_speed(0.01);
  const RobotParams fast = at_top_speed(0.5);
  for (const bool fast_first : {false, true}) {
    World world(test::empty_arena(1.0, 1.0), fast_first ? std::vector<RobotParams>{fast, slow}
                                                         : std::vector<RobotParams>{slow, fast});
    const Pose still{0.64, 0.5, 0.0}, driving{0.74, 0.5, std::numbers::pi};
    const std::array<Pose, 2> starts = fast_first ? std::array<Pose, 2>{driving, still} : std::array<Pose, 2>{still, driving};
    world.reset(starts);
    Rng rng(1);
    const std::array<DriveCommand, 2> commands =
        fast_first ? std::array<DriveCommand, 2>{DriveCommand{1, 1}, DriveCommand{0, 0}}
                   : std::array<DriveCommand, 2>{DriveCommand{0, 0}, DriveCommand{1, 1}};
    bool met = false;
    for (int step = 0; step < 3; ++step) {
      world.step(commands, rng);
      ASSERT_GT(distance(world.state(0).pose, world.state(1).pose), 2 * slow.body_radius_m - 1e-3) << step;
      met = met || (world.state(0).collided && world.state(1).collided);
    }
    EXPECT_TRUE(met) << (fast_first ? "fast first" : "slow first");
  }
}

// A robot pushed into a third, faster than its own top speed would take it there: the contact
// is still felt by both.
TEST(SimGroup, ARobotPushedIntoAnotherCollidesWithIt) {
  const RobotParams slow = at_top_speed(0.001);
  const RobotParams fast = at_top_speed(0.5);
  World world(test::empty_arena(1.0, 1.0), std::vector<RobotParams>{fast, slow, slow});
  const double r = slow.body_radius_m;
  const std::array<Pose, 3> starts = {Pose{0.5 - 2 * r - 0.001, 0.5, 0.0}, Pose{0.5, 0.5, 0.0},
                                      Pose{0.5 + 2 * r + 0.02, 0.5, 0.0}};
  world.reset(starts);
  Rng rng(1);
  const std::array<DriveCommand, 3> commands = {DriveCommand{1, 1}, DriveCommand{0, 0}, DriveCommand{0, 0}};
  int touching = 0;
  for (int step = 0; step < 6; ++step) {
    world.step(commands, rng);
    const double bc = distance(world.state(1).pose, world.state(2).pose);
    ASSERT_GT(bc, 2 * r - 1e-3) << step;
    if (bc < 2 * r + 1e-4) {
      ++touching;
      EXPECT_TRUE(world.state(2).collided) << step;
    }
  }
  EXPECT_GT(touching, 0);
}

TEST(SimGroup, TwoThymiosMeetAtTheirOutlines) {
  // Face to face, their front arcs (8 cm ahead of the axle) meet: the centres stop 16 cm apart.
  World world(test::empty_arena(1.0, 1.0), std::vector<RobotParams>(2, test::thymio_like()));
  const std::array<Pose, 2> starts = {Pose{0.3, 0.5, 0.0}, Pose{0.7, 0.5, std::numbers::pi}};
  world.reset(starts);
  Rng rng(1);
  const std::array<DriveCommand, 2> ahead = {DriveCommand{1, 1}, DriveCommand{1, 1}};
  bool met = false;
  for (int step = 0; step < 40; ++step) {
    world.step(ahead, rng);
    ASSERT_GT(distance(world.state(0).pose, world.state(1).pose), 0.16 - 1e-3) << step;
    met = met || world.state(0).collided;
  }
  EXPECT_TRUE(met);
  EXPECT_LT(distance(world.state(0).pose, world.state(1).pose), 0.16 + 2e-3);
}

// Bodies of different shapes in one world: a Khepera's disc and a Thymio's outline meet where
// their surfaces do (the Thymio's front arc 8 cm ahead of its axle), and a Khepera's IR sees a
// larger disc (an e-puck's 3.7 cm) exactly as a cylinder of that radius.
TEST(SimGroup, BodiesOfDifferentShapesMeetAndSeeEachOtherAsTheyAre) {
  const RobotParams thymio = test::thymio_like();
  RobotParams k = test::robot_with_inertia(false);
  k.physics_substeps = thymio.physics_substeps;   // one Bullet step moves both
  World world(test::empty_arena(1.0, 1.0), std::vector<RobotParams>{k, thymio});
  const std::array<Pose, 2> starts = {Pose{0.3, 0.5, 0.0}, Pose{0.7, 0.5, std::numbers::pi}};
  world.reset(starts);
  Rng rng(1);
  const std::array<DriveCommand, 2> ahead = {DriveCommand{1, 1}, DriveCommand{1, 1}};
  const double touching = k.body_radius_m + 0.08;
  bool met = false;
  for (int step = 0; step < 60; ++step) {
    world.step(ahead, rng);
    ASSERT_GT(distance(world.state(0).pose, world.state(1).pose), touching - 1e-3) << step;
    met = met || (world.state(0).collided && world.state(1).collided);
  }
  EXPECT_TRUE(met);
  EXPECT_LT(distance(world.state(0).pose, world.state(1).pose), touching + 2e-3);

  RobotParams epuck = k;
  epuck.body_radius_m = 0.037;
  const Pose p0{0.5, 0.5, 0.2};
  const Vec2 q{p0.x_m + (k.body_radius_m + epuck.body_radius_m + 0.01) * std::cos(p0.heading_rad),
               p0.y_m + (k.body_radius_m + epuck.body_radius_m + 0.01) * std::sin(p0.heading_rad)};
  World pair(test::empty_arena(1.0, 1.0), std::vector<RobotParams>{k, epuck});
  const std::array<Pose, 2> facing = {p0, Pose{q.x, q.y, p0.heading_rad + std::numbers::pi}};
  pair.reset(facing);
  std::array<double, kIrSensors> seen{};
  Rng r1(1);
  pair.read_ir(seen, r1);
  EXPECT_EQ(seen, ir_beside_cylinder(k, p0, q, epuck.body_radius_m));
  EXPECT_GT(*std::max_element(seen.begin(), seen.end()), 0.0);
}

TEST(SimGroup, AGroupMustShareItsDriveAndItsStepAndStartApart) {
  std::vector<RobotParams> mixed = {test::robot_with_inertia(false), navigator()};
  EXPECT_THROW(World(test::empty_arena(1.0, 1.0), mixed), std::invalid_argument);
  EXPECT_THROW(World(test::empty_arena(1.0, 1.0), std::vector<RobotParams>{}), std::invalid_argument);
  World pair(test::empty_arena(1.0, 1.0), std::vector<RobotParams>(2, test::robot_with_inertia(false)));
  const Pose one{0.5, 0.5, 0.0};
  EXPECT_THROW(pair.reset(one), std::invalid_argument);
  Rng rng(1);
  const std::array<DriveCommand, 1> too_few = {};
  EXPECT_THROW(pair.step(too_few, rng), std::invalid_argument);
  EXPECT_THROW(pair.step(1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(pair.step(1.0, 1.0, rng), std::invalid_argument);
  // One Bullet step moves every body: one substep for all.
  RobotParams finer = test::robot_with_inertia(false);
  finer.physics_substeps = 10;
  EXPECT_THROW(World(test::empty_arena(1.0, 1.0), std::vector<RobotParams>{test::robot_with_inertia(false), finer}),
               std::invalid_argument);
  // Overlapping starts are refused, naming the robots.
  const std::array<Pose, 2> overlapping = {Pose{0.5, 0.5, 0.0}, Pose{0.52, 0.5, 0.0}};
  try {
    pair.reset(overlapping);
    FAIL() << "overlapping starts accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("robots 0 and 1"), std::string::npos) << e.what();
  }
}

TEST(SimGroup, TheGridFindsEveryRobotWithinAReach) {
  std::mt19937_64 gen(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const std::size_t n : {1U, 2U, 7U, 50U, 300U}) {
    // Some centres outside the arena (a robot pushed through a corner by rounding): counted in
    // the nearest cell, found all the same.
    std::vector<Vec2> centres(n);
    for (Vec2& c : centres) c = {3.0 * unit(gen) - 0.5, 2.0 * unit(gen) - 0.5};
    Neighbours grid(n, 2.0, 1.0, 0.1);
    grid.build(centres);
    for (int q = 0; q < 200; ++q) {
      const Vec2 p{3.0 * unit(gen) - 0.5, 2.0 * unit(gen) - 0.5};
      const double reach = 0.5 * unit(gen);
      std::vector<std::size_t> found;
      grid.near(p, reach, [&](std::size_t j) { found.push_back(j); });
      const std::set<std::size_t> unique(found.begin(), found.end());
      ASSERT_EQ(unique.size(), found.size()) << "a robot reported twice";
      for (std::size_t j = 0; j < n; ++j) {
        if (std::hypot(centres[j].x - p.x, centres[j].y - p.y) <= reach) {
          ASSERT_TRUE(unique.count(j)) << n << " robots, robot " << j << " missed";
        }
      }
    }
  }
}

TEST(SimGroup, RaysMeetAnOutlineWhereItIs) {
  // A Thymio-like outline placed at the origin facing +x: its flat back 3 cm behind the axle,
  // its front arc 8 cm ahead.
  const std::vector<Vec2> outline = test::thymio_outline();
  const PlacedBody body{{0.0, 0.0}, 0.08, outline};
  EXPECT_NEAR(ray_body_hit(body, {-0.5, 0.0}, 1.0, 0.0), 0.47, 1e-12);
  EXPECT_NEAR(ray_body_hit(body, {0.5, 0.0}, -1.0, 0.0), 0.42, 1e-9);
  EXPECT_EQ(ray_body_hit(body, {0.0, 0.0}, 1.0, 0.0), 0.0);   // from inside
  EXPECT_TRUE(std::isinf(ray_body_hit(body, {-0.5, 0.07}, 1.0, 0.0)));   // passes its corner by
  EXPECT_TRUE(std::isinf(ray_body_hit(body, {-0.5, 0.0}, -1.0, 0.0)));   // points away
  // A disc: the circle's hit.
  const PlacedBody disc{{1.0, 1.0}, 0.1, {}};
  EXPECT_NEAR(ray_body_hit(disc, {0.0, 1.0}, 1.0, 0.0), 0.9, 1e-12);
}

}  // namespace
}  // namespace esc::sim
