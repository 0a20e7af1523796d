// The floor on its own (floor.hpp, no Bullet, no body): the accumulator's exact units, the
// sweep grid and the reach edges follow the centre's positions alone, and random zones
// keep clear of obstacles with their lights above them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "runtime/sim/floor.hpp"
#include "sim_test_util.hpp"

namespace esc::sim {
namespace {

TEST(SimFloor, TheAccumulatorDrainsOutsideAndRefillsInsideARechargeZone) {
  ArenaSpec a = test::empty_arena(0.6, 0.6);
  Zone recharge;
  recharge.center_m = {0.5, 0.5};
  recharge.radius_m = 0.05;
  recharge.recharge = true;
  a.zones.push_back(recharge);
  RobotParams r;
  r.energy.enabled = true;
  r.energy.discharge_steps = 3;   // full = 3 * 2 * 2 substeps = 12 units
  r.energy.recharge_steps = 2;
  r.physics_substeps = 2;
  Floor floor(a, r);
  FloorState s;
  const Vec2 outside{0.1, 0.1};
  const Vec2 inside{0.5, 0.52};
  floor.reset(outside, s);
  EXPECT_EQ(s.energy, 1.0);
  for (const double units : {8.0, 4.0, 0.0}) {   // 2 units per substep outside
    floor.substep(outside);
    floor.substep(outside);
    floor.observe(outside, s);
    EXPECT_EQ(s.energy, units / 12.0);
    EXPECT_EQ(s.energy_empty, units == 0.0);
    EXPECT_EQ(s.in_zone, 0U);
  }
  for (const double units : {6.0, 12.0, 12.0}) {   // 3 units per substep inside, up to full
    floor.substep(inside);
    floor.substep(inside);
    floor.observe(inside, s);
    EXPECT_EQ(s.energy, units / 12.0);
    EXPECT_FALSE(s.energy_empty);
    EXPECT_EQ(s.in_zone, 1U);
    EXPECT_FALSE(s.ground);   // the zone is not visible
  }
  floor.substep(outside);
  floor.reset(outside, s);
  EXPECT_EQ(s.energy, 1.0);
}

TEST(SimFloor, CellsAndReachFollowTheCentre) {
  ArenaSpec a = test::empty_arena(0.6, 0.6);   // 15 x 15 cells of 4 cm
  LightSource lamp;
  lamp.position_m = {0.3, 0.3};
  a.lights.push_back(lamp);                     // reach 4.75 cm
  Floor floor(a, RobotParams{});
  ASSERT_EQ(floor.sweep_columns(), 15);
  FloorState s;
  floor.reset({0.1, 0.3}, s);                   // column 2
  EXPECT_EQ(s.cells_visited, 1);
  EXPECT_FALSE(s.new_cell);
  const auto at = [&](double x) {
    floor.observe({x, 0.3}, s);
    return std::tuple{s.new_cell, s.cells_visited, s.reached, s.reach_count[0]};
  };
  EXPECT_EQ(at(0.105), std::tuple(false, 1, 0U, 0));   // still column 2
  EXPECT_EQ(at(0.125), std::tuple(true, 2, 0U, 0));    // column 3
  EXPECT_EQ(at(0.1), std::tuple(false, 2, 0U, 0));     // back: visited already
  EXPECT_EQ(at(0.26), std::tuple(true, 3, 1U, 1));     // 4 cm from the light: a rising edge
  EXPECT_EQ(at(0.27), std::tuple(false, 3, 0U, 1));    // still within reach: no edge
  EXPECT_EQ(at(0.22), std::tuple(true, 4, 0U, 1));     // out of reach
  EXPECT_EQ(at(0.26), std::tuple(false, 4, 1U, 2));    // back in: counted again
  floor.reset({0.3, 0.3}, s);                          // placed within reach
  EXPECT_EQ(at(0.31), std::tuple(false, 1, 0U, 0));    // not an entry
}

TEST(SimFloor, RandomZonesKeepClearOfObstaclesAndCarryTheirLights) {
  ArenaSpec a = test::empty_arena(0.6, 0.6);
  a.cylinders.push_back({{0.3, 0.3}, 0.15});
  Zone z;
  z.radius_m = 0.05;
  z.random_position = true;
  a.zones.push_back(z);
  LightSource above;
  above.above_zone = 0;
  a.lights.push_back(above);
  Floor floor(a, RobotParams{});
  const StaticGeometry2D geometry(a);
  Rng rng(4);
  for (int i = 0; i < 200; ++i) {
    floor.place_zones(rng, geometry);
    const Vec2 c = floor.zone_centers()[0];
    EXPECT_GE(test::obstacle_clearance(a, c.x, c.y), 0.05) << i;
    EXPECT_GE(std::min({c.x, c.y, 0.6 - c.x, 0.6 - c.y}), 0.05) << i;
    EXPECT_EQ(floor.light_positions()[0].x, c.x);
    EXPECT_EQ(floor.light_positions()[0].y, c.y);
    EXPECT_EQ(floor.lights()[0].x_m, c.x);
    EXPECT_TRUE(floor.in_zone(0, {c.x + 0.049, c.y}));
    EXPECT_FALSE(floor.in_zone(0, {c.x + 0.051, c.y}));
  }
  // Without a random zone nothing is drawn.
  a.zones[0].random_position = false;
  Floor fixed(a, RobotParams{});
  Rng before(9);
  Rng after = before;
  fixed.place_zones(after, geometry);
  EXPECT_EQ(after.next(), before.next());
}

}  // namespace
}  // namespace esc::sim
