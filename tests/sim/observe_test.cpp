// The world's new state reaches the observable frame (runtime/eval/observe.*), and the
// frame's layout: slot blocks, parametrised observables, param, then the navigator's.
#include <gtest/gtest.h>

#include <array>
#include <numbers>
#include <set>
#include <vector>
#include <cmath>

#include "runtime/eval/observe.hpp"
#include "sim_test_util.hpp"

namespace esc::eval {
namespace {

using expr::Frame;
namespace slot = expr::slot;

TEST(SimObserve, FrameLayout) {
  // The navigator's observables come after `param`, which kept its slots, then the ground
  // sensors and the bumpers, then a group's observables, which end the frame.
  EXPECT_EQ(slot::param, 44U);
  EXPECT_EQ(expr::kFrameSizeBeforeNavigator, slot::param + expr::kMaxParams);
  EXPECT_EQ(slot::x, expr::kFrameSizeBeforeNavigator);
  EXPECT_EQ(slot::ground_sensor, slot::radar + expr::kRadarCount);
  EXPECT_EQ(slot::bumper, slot::ground_sensor + expr::kGroundSensorCount);
  EXPECT_EQ(slot::robots, slot::bumper + expr::kBumperCount);
  EXPECT_EQ(slot::clusters, slot::spread + 1);
  EXPECT_EQ(expr::kFrameSize, slot::cluster_size + expr::kMaxClusterRadii);
  // Every slot belongs to exactly one observable, parametrised block or param.
  std::set<expr::Slot> used;
  const auto claim = [&](expr::Slot first, expr::Slot count) {
    for (expr::Slot s = first; s < first + count; ++s) EXPECT_TRUE(used.insert(s).second) << s;
  };
  for (const auto& o : expr::kObservables) {
    if (o.name == "com_speed") continue;  // checked below
    claim(o.first, o.count);
  }
  for (const auto& o : expr::kParametrised) claim(o.first, o.count);
  claim(slot::param, expr::kMaxParams);
  claim(slot::com_speed, 1);
  claim(slot::acting, 1);   // written by the evaluator, read by using(B)
  EXPECT_EQ(used.size(), expr::kFrameSize);
  EXPECT_EQ(*used.rbegin(), expr::kFrameSize - 1);
  // in/reached are not plain observables.
  EXPECT_FALSE(expr::find_observable("in"));
  EXPECT_FALSE(expr::find_observable("reached"));
  ASSERT_TRUE(expr::find_parametrised("in"));
  EXPECT_EQ(expr::find_parametrised("in")->first, slot::in_zone);
  EXPECT_EQ(expr::find_parametrised("in")->count, sim::kMaxZones);
  EXPECT_EQ(expr::find_parametrised("reached")->argument, "light");
  EXPECT_EQ(expr::find_parametrised("reached")->count, sim::kMaxLights);
  ASSERT_TRUE(expr::find_observable("light"));
  EXPECT_EQ(expr::find_observable("light")->count, 8U);
  for (const char* n : {"energy", "com_speed", "ground", "new_cell", "cells_visited"})
    EXPECT_TRUE(expr::find_observable(n)) << n;
  EXPECT_EQ(expr::find_observable("range")->count, static_cast<expr::Slot>(sim::kMaxRangefinders));
  EXPECT_EQ(expr::find_observable("radar")->count, static_cast<expr::Slot>(sim::kMaxRadars));
}

// A maze corridor: a wall 20 cm ahead of a robot facing +y, a goal 40 cm to its right.
TEST(SimObserve, NavigationReachesTheFrame) {
  constexpr double kDeg = std::numbers::pi / 180;
  sim::ArenaSpec a = sim::test::empty_arena(1.0, 1.0);
  a.walls.push_back({{0.2, 0.6}, {0.8, 0.6}, 0.01});
  a.goal = sim::Vec2{0.9, 0.4};
  sim::RobotParams p;
  p.rangefinders.angles_rad = {0.0, 90 * kDeg, -90 * kDeg, 180 * kDeg};
  p.rangefinders.range_m = 0.4;
  p.radars = 4;
  sim::World w(a, p);
  w.reset({0.5, 0.4, 90 * kDeg});
  const std::array<double, sim::kIrSensors> ir{};
  Frame f{};
  observe_robot(w, 0, ir, f);
  const sim::Pose& at = w.state().pose;   // as Bullet holds it
  EXPECT_NEAR(at.x_m, 0.5, 1e-9);
  EXPECT_EQ(f[slot::x], at.x_m);
  EXPECT_EQ(f[slot::y], at.y_m);
  EXPECT_EQ(f[slot::heading], at.heading_rad);
  EXPECT_NEAR(f[slot::heading], std::numbers::pi / 2, 1e-9);
  EXPECT_NEAR(f[slot::goal_distance], 0.4, 1e-9);
  // Ahead: the wall's near face at y = 0.595, 0.195 away; left and right: the side walls 0.5
  // away, beyond range; behind: the bottom wall 0.4 away, at the range.
  EXPECT_NEAR(f[slot::range], 0.195 / 0.4, 1e-9);
  EXPECT_EQ(f[slot::range + 1], 1.0);
  EXPECT_EQ(f[slot::range + 2], 1.0);
  EXPECT_NEAR(f[slot::range + 3], 1.0, 1e-9);
  for (expr::Slot i = 4; i < expr::kRangeCount; ++i) EXPECT_EQ(f[slot::range + i], 0.0);   // no such rangefinder
  // The goal lies to the right: slice 3 of front, left, back, right.
  EXPECT_EQ(f[slot::radar], 0.0);
  EXPECT_EQ(f[slot::radar + 1], 0.0);
  EXPECT_EQ(f[slot::radar + 2], 0.0);
  EXPECT_EQ(f[slot::radar + 3], 1.0);
  // Turned to face the goal: slice 0, and the slice that fired before is cleared.
  w.reset({0.5, 0.4, 0.0});
  observe_robot(w, 0, ir, f);
  EXPECT_EQ(f[slot::radar], 1.0);
  EXPECT_EQ(f[slot::radar + 3], 0.0);
  EXPECT_NEAR(f[slot::range + 1], 0.195 / 0.4, 1e-9);   // the wall is now to the left
}

// Without a goal, rangefinders or radars, their slots are never written.
TEST(SimObserve, NavigationSlotsStayZeroWithoutTheirSensors) {
  sim::ArenaSpec a = sim::test::empty_arena(0.6, 0.6);
  sim::World w(a, sim::RobotParams{});
  w.reset({0.3, 0.2, 1.0});
  Frame f{};
  observe_robot(w, 0, std::array<double, sim::kIrSensors>{}, f);
  EXPECT_NEAR(f[slot::y], 0.2, 1e-9);
  EXPECT_NEAR(f[slot::heading], 1.0, 1e-9);
  EXPECT_EQ(f[slot::goal_distance], 0.0);
  for (expr::Slot s = slot::range; s < expr::kFrameSize; ++s) EXPECT_EQ(f[s], 0.0) << s;
}

TEST(SimObserve, WorldStateReachesTheFrame) {
  sim::ArenaSpec a = sim::test::empty_arena(0.6, 0.6);
  sim::Zone z;
  z.center_m = {0.3, 0.3};
  z.radius_m = 0.05;
  z.visible = true;
  a.zones.push_back(z);                     // zone 0: visible, not recharging
  sim::Zone r = z;
  r.center_m = {0.5, 0.3};
  r.recharge = true;
  r.visible = false;
  a.zones.push_back(r);                     // zone 1: invisible recharge
  a.lights.push_back({{0.1, 0.1}, 0.0, 1.0, -1});
  a.lights.push_back({{0.0, 0.0}, 0.0, 1.0, 1});  // above zone 1
  sim::RobotParams p;
  p.motor.inertia = false;
  p.energy.enabled = true;
  sim::World w(a, p);
  w.reset({0.3, 0.3, 0.0});
  Rng rng(1);
  std::array<double, sim::kIrSensors> ir{};
  std::array<double, sim::kLightSensors> light{};
  Frame f{};
  w.read_ir(ir, rng);
  w.read_light(light, rng);
  observe_robot(w, 0, ir, f);
  observe_light(light, f);
  EXPECT_EQ(f[slot::energy], 1.0);
  EXPECT_EQ(f[slot::in_zone], 1.0);
  EXPECT_EQ(f[slot::in_zone + 1], 0.0);
  EXPECT_EQ(f[slot::ground], 1.0);
  EXPECT_EQ(f[slot::cells_visited], 1.0);
  EXPECT_EQ(f[slot::new_cell], 0.0);
  EXPECT_GT(f[slot::light + 2], 0.0);  // the light above zone 1, ahead
  for (std::size_t i = 0; i < 8; ++i) EXPECT_EQ(f[slot::light + i], light[i]);
  int reached_1 = 0;
  int new_cells = 0;
  for (int i = 0; i < 20; ++i) {  // drive into the recharge zone, to the light above it
    w.step(1.0, 1.0);
    w.read_ir(ir, rng);
    observe_robot(w, 0, ir, f);
    EXPECT_EQ(f[slot::com_speed], f[slot::speed]);
    EXPECT_NEAR(f[slot::speed], 1.0, 1e-6);
    EXPECT_EQ(f[slot::energy], w.state().floor.energy);
    EXPECT_EQ(f[slot::in_zone + 1], (w.state().floor.in_zone & 2U) != 0 ? 1.0 : 0.0);
    EXPECT_EQ(f[slot::ground], w.state().floor.ground ? 1.0 : 0.0);
    reached_1 += static_cast<int>(f[slot::reached + 1]);
    EXPECT_EQ(f[slot::reached], 0.0);
    new_cells += static_cast<int>(f[slot::new_cell]);
    EXPECT_EQ(f[slot::cells_visited], w.state().floor.cells_visited);
  }
  EXPECT_EQ(reached_1, 1);
  EXPECT_EQ(new_cells + 1, w.state().floor.cells_visited);
  EXPECT_EQ(f[slot::in_zone + 1], 1.0);
  EXPECT_EQ(f[slot::ground], 0.0);  // zone 1 is invisible
  EXPECT_LT(f[slot::energy], 1.0);
  EXPECT_GT(f[slot::energy], 0.9);
}

// The group's observables, against the robots' centres computed by hand: a 3-4-5 triangle.
TEST(SimObserve, GroupObservables) {
  sim::ArenaSpec arena;
  arena.width_m = 2.0;
  arena.height_m = 1.0;
  sim::World w(arena, std::vector<sim::RobotParams>(3, sim::RobotParams{}));
  const std::array<sim::Pose, 3> poses = {sim::Pose{0.2, 0.2, 0.0}, sim::Pose{0.5, 0.2, 1.0}, sim::Pose{0.2, 0.6, 2.0}};
  w.reset(poses);
  std::vector<Frame> frames(3);
  const sim::Vec2 start{0.0, 0.0};
  observe_group(w, start, true, frames);
  const double cx = 0.9 / 3, cy = 1.0 / 3;
  for (std::size_t i = 0; i < 3; ++i) {
    const Frame& f = frames[i];
    EXPECT_EQ(f[slot::robots], 3.0);
    EXPECT_NEAR(f[slot::centroid_x], cx, 1e-15);
    EXPECT_NEAR(f[slot::centroid_y], cy, 1e-15);
    EXPECT_NEAR(f[slot::centroid_moved], std::hypot(cx, cy), 1e-15);
    EXPECT_NEAR(f[slot::centroid_distance], std::hypot(poses[i].x_m - cx, poses[i].y_m - cy), 1e-15);
    EXPECT_NEAR(f[slot::robot_distance], (0.3 + 0.4 + 0.5) / 3, 1e-15);
  }
  EXPECT_NEAR(frames[0][slot::nearest_robot], 0.3, 1e-15);
  EXPECT_NEAR(frames[1][slot::nearest_robot], 0.3, 1e-15);
  EXPECT_NEAR(frames[2][slot::nearest_robot], 0.4, 1e-15);
  double spread = 0.0;
  for (const sim::Pose& p : poses) spread = std::max(spread, std::hypot(p.x_m - cx, p.y_m - cy));
  EXPECT_NEAR(frames[0][slot::spread], spread, 1e-15);
  // Without `pairs`, the observables made from every pair are not written.
  std::vector<Frame> unpaired(3);
  observe_group(w, start, false, unpaired);
  EXPECT_EQ(unpaired[0][slot::nearest_robot], 0.0);
  EXPECT_EQ(unpaired[0][slot::robot_distance], 0.0);
  EXPECT_NEAR(unpaired[2][slot::centroid_distance], frames[2][slot::centroid_distance], 0.0);
  // A robot alone: its own centroid, no neighbour nearer than the arena's diagonal.
  sim::World alone(arena, sim::RobotParams{});
  alone.reset(poses[0]);
  std::vector<Frame> one(1);
  observe_group(alone, {0.2, 0.2}, true, one);
  EXPECT_EQ(one[0][slot::robots], 1.0);
  EXPECT_EQ(one[0][slot::centroid_distance], 0.0);
  EXPECT_EQ(one[0][slot::centroid_moved], 0.0);
  EXPECT_EQ(one[0][slot::spread], 0.0);
  EXPECT_EQ(one[0][slot::robot_distance], 0.0);
  EXPECT_NEAR(one[0][slot::nearest_robot], std::hypot(2.0, 1.0), 1e-15);
}

// Clusters within a radius: five robots, a pair 0.3 m apart beside a chain of three 0.2 m
// apart (its ends 0.4 m apart), far from the pair. Within 0.25 m: the chain and two
// singletons; within 0.35 m: the pair and the chain; within 0.1 m: five singletons.
TEST(SimObserve, ClustersWithinEachRadius) {
  sim::ArenaSpec arena;
  arena.width_m = 3.0;
  arena.height_m = 1.0;
  sim::World w(arena, std::vector<sim::RobotParams>(5, sim::RobotParams{}));
  const std::array<sim::Pose, 5> poses = {sim::Pose{0.2, 0.2, 0.0}, sim::Pose{0.5, 0.2, 0.0}, sim::Pose{1.5, 0.5, 0.0},
                                          sim::Pose{1.7, 0.5, 0.0}, sim::Pose{1.9, 0.5, 0.0}};
  w.reset(poses);
  std::vector<Frame> frames(5);
  std::vector<std::size_t> parent(5), size(5);
  const std::array<double, 3> radii = {0.25, 0.35, 0.1};
  observe_clusters(w, radii, frames, parent, size);
  for (const Frame& f : frames) {
    EXPECT_EQ(f[slot::clusters + 0], 3.0);
    EXPECT_EQ(f[slot::largest_cluster + 0], 3.0);
    EXPECT_EQ(f[slot::clusters + 1], 2.0);
    EXPECT_EQ(f[slot::largest_cluster + 1], 3.0);
    EXPECT_EQ(f[slot::clusters + 2], 5.0);
    EXPECT_EQ(f[slot::largest_cluster + 2], 1.0);
    EXPECT_EQ(f[slot::clusters + 3], 0.0) << "a radius not read is not written";
  }
  const std::array<double, 5> within_25 = {1, 1, 3, 3, 3}, within_35 = {2, 2, 3, 3, 3};
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_EQ(frames[i][slot::cluster_size + 0], within_25[i]) << i;
    EXPECT_EQ(frames[i][slot::cluster_size + 1], within_35[i]) << i;
    EXPECT_EQ(frames[i][slot::cluster_size + 2], 1.0) << i;
  }
  // A robot alone is one cluster of one.
  sim::World alone(arena, sim::RobotParams{});
  alone.reset(poses[0]);
  std::vector<Frame> one(1);
  observe_clusters(alone, radii, one, std::span(parent).first(1), std::span(size).first(1));
  EXPECT_EQ(one[0][slot::clusters], 1.0);
  EXPECT_EQ(one[0][slot::largest_cluster + 1], 1.0);
  EXPECT_EQ(one[0][slot::cluster_size + 2], 1.0);
}

}  // namespace
}  // namespace esc::eval
