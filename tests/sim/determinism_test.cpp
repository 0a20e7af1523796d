// A trajectory depends only on its start pose, commands and noise stream: a reused World
// after reset() gives bit-identical results to a fresh one.
#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <numbers>
#include <utility>
#include <vector>

#include "sim_test_util.hpp"

namespace esc::sim {
namespace {

struct Trace {
  std::vector<double> values;
  int collisions = 0;
};

ArenaSpec cluttered_arena() {
  ArenaSpec a = test::empty_arena(0.6, 0.6);
  a.cylinders.push_back({{0.2, 0.4}, 0.03});
  a.cylinders.push_back({{0.45, 0.2}, 0.025});
  a.boxes.push_back({{0.42, 0.45}, {0.1, 0.04}, 0.7});
  return a;
}

RobotParams noisy_robot() {
  RobotParams r;
  r.ir.noise_sd = 0.05;
  return r;
}

// Commands change every 10 steps, biased forwards so the robot meets walls and corners.
Trace run(World& world, const Pose& start, std::uint64_t seed, int steps) {
  world.reset(start);
  Rng commands(seed);
  Rng noise(seed + 1000);
  Trace t;
  std::array<double, kIrSensors> ir{};
  double l = 0.0, r = 0.0;
  for (int i = 0; i < steps; ++i) {
    if (i % 10 == 0) {
      l = commands.uniform(-0.5, 1.0);
      r = commands.uniform(-0.5, 1.0);
    }
    world.read_ir(ir, noise);
    world.step(l, r);
    const RobotState& s = world.state();
    t.values.insert(t.values.end(), ir.begin(), ir.end());
    t.values.insert(t.values.end(), {s.pose.x_m, s.pose.y_m, s.pose.heading_rad,
                                     s.wheel_speed_mps[0], s.wheel_speed_mps[1],
                                     s.displacement_m, s.forward_displacement_m});
    t.collisions += s.collided ? 1 : 0;
  }
  return t;
}

bool bit_identical(const Trace& a, const Trace& b) {
  return a.collisions == b.collisions && a.values.size() == b.values.size() &&
         std::memcmp(a.values.data(), b.values.data(), a.values.size() * sizeof(double)) == 0;
}

TEST(SimDeterminism, ReusedWorldMatchesFreshWorldBitForBit) {
  const Pose start{0.3, 0.25, 0.4};
  const int steps = 3000;
  World fresh(cluttered_arena(), noisy_robot());
  const Trace expected = run(fresh, start, 42, steps);
  EXPECT_GT(expected.collisions, 50);  // the trajectory does exercise contacts

  World reused(cluttered_arena(), noisy_robot());
  const Trace other = run(reused, {0.1, 0.1, -2.0}, 7, 2000);  // different history
  EXPECT_FALSE(bit_identical(other, expected));
  EXPECT_TRUE(bit_identical(run(reused, start, 42, steps), expected));
  // Stopped in contact mid-trajectory, then reset: still identical.
  run(reused, {0.5, 0.5, 0.0}, 9, 137);
  EXPECT_TRUE(bit_identical(run(reused, start, 42, steps), expected));
  // Moving keeps the state.
  World moved(std::move(reused));
  EXPECT_TRUE(bit_identical(run(moved, start, 42, steps), expected));
  World assigned(test::empty_arena(1.0, 1.0), RobotParams{});
  assigned = std::move(moved);
  EXPECT_TRUE(bit_identical(run(assigned, start, 42, steps), expected));
}

TEST(SimDeterminism, ManyWorldsAgree) {
  const Pose start{0.25, 0.3, -1.0};
  World a(cluttered_arena(), noisy_robot());
  const Trace expected = run(a, start, 3, 1500);
  for (std::uint64_t history = 0; history < 5; ++history) {
    World b(cluttered_arena(), noisy_robot());
    Rng rng(history);
    run(b, b.random_free_pose(rng), 100 + history, 500);
    EXPECT_TRUE(bit_identical(run(b, start, 3, 1500), expected)) << history;
  }
}

// The same with lights (one above a random recharge zone), zones, energy, light noise and
// the sweep grid: every epoch starts with begin_epoch from its own stream.
ArenaSpec homing_arena() {
  ArenaSpec a = cluttered_arena();
  test::add_homing_features(a, {.recharge_radius_m = 0.06,
                                .mark_center_m = {0.1, 0.5},
                                .mark_size_m = {0.15, 0.1},
                                .light_height_m = 0.05,
                                .free_light = {{0.55, 0.05}, 0.0, 0.5, -1}});
  return a;
}

RobotParams homing_robot() {
  RobotParams r = noisy_robot();
  r.light.noise_sd = 0.03;
  r.energy.enabled = true;
  r.energy.discharge_steps = 120;  // empties within the runs below
  r.energy.recharge_steps = 30;
  return r;
}

Trace run_homing(World& world, std::uint64_t seed, int epochs, int steps) {
  Trace t;
  Rng commands(seed);
  std::array<double, kIrSensors> ir{};
  std::array<double, kLightSensors> light{};
  double l = 0.0, r = 0.0;
  for (int e = 0; e < epochs; ++e) {
    Rng rng(seed, {static_cast<std::uint64_t>(e)});
    const Pose p = world.begin_epoch(rng);
    t.values.insert(t.values.end(), {p.x_m, p.y_m, world.zone_centers()[0].x,
                                     world.light_positions()[0].y});
    for (int i = 0; i < steps; ++i) {
      if (i % 10 == 0) {
        l = commands.uniform(-0.5, 1.0);
        r = commands.uniform(-0.5, 1.0);
      }
      world.read_ir(ir, rng);
      world.read_light(light, rng);
      world.step(l, r);
      const RobotState& s = world.state();
      t.values.insert(t.values.end(), ir.begin(), ir.end());
      t.values.insert(t.values.end(), light.begin(), light.end());
      t.values.insert(t.values.end(),
                      {s.pose.x_m, s.pose.y_m, s.pose.heading_rad, s.floor.energy,
                       static_cast<double>(s.floor.in_zone), static_cast<double>(s.floor.reached),
                       static_cast<double>(s.floor.reach_count[0] + 10 * s.floor.reach_count[1]),
                       s.floor.ground ? 1.0 : 0.0, s.floor.new_cell ? 1.0 : 0.0,
                       static_cast<double>(s.floor.cells_visited)});
      t.collisions += s.collided ? 1 : 0;
      if (s.floor.energy_empty) break;
    }
  }
  return t;
}

TEST(SimDeterminism, LightsZonesEnergyReusedMatchesFresh) {
  World fresh(homing_arena(), homing_robot());
  const Trace expected = run_homing(fresh, 5, 6, 400);
  World reused(homing_arena(), homing_robot());
  const Trace other = run_homing(reused, 77, 4, 300);  // a different history
  EXPECT_FALSE(bit_identical(other, expected));
  EXPECT_TRUE(bit_identical(run_homing(reused, 5, 6, 400), expected));
  World moved(std::move(reused));
  EXPECT_TRUE(bit_identical(run_homing(moved, 5, 6, 400), expected));
}

}  // namespace
}  // namespace esc::sim
