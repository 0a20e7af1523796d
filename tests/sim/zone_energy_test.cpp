// Zones (membership, ground sensor, random placement), the energy accumulator (exact
// arithmetic over scripted trajectories) and reached(light) events.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "sim_test_util.hpp"

namespace esc::sim {
namespace {

Zone circle(double x, double y, double r, bool recharge = false, bool visible = false) {
  Zone z;
  z.shape = ZoneShape::Circle;
  z.center_m = {x, y};
  z.radius_m = r;
  z.recharge = recharge;
  z.visible = visible;
  return z;
}

Zone rectangle(double x, double y, double sx, double sy, bool recharge = false,
               bool visible = false) {
  Zone z;
  z.shape = ZoneShape::Rectangle;
  z.center_m = {x, y};
  z.size_m = {sx, sy};
  z.recharge = recharge;
  z.visible = visible;
  return z;
}

RobotParams energy_robot(int discharge = 285, int recharge = 100, int substeps = 2) {
  RobotParams r;
  r.motor.inertia = false;  // speed = command at once: substep positions are known
  r.physics_substeps = substeps;
  r.energy.enabled = true;
  r.energy.discharge_steps = discharge;
  r.energy.recharge_steps = recharge;
  return r;
}

// ---- energy ---------------------------------------------------------------------------

TEST(SimEnergy, FullUntilEnabled) {
  World world(test::empty_arena(0.6, 0.6), RobotParams{});
  world.reset({0.3, 0.3, 0.0});
  for (int i = 0; i < 1000; ++i) world.step(0.0, 0.0);
  EXPECT_EQ(world.state().floor.energy, 1.0);
  EXPECT_FALSE(world.state().floor.energy_empty);
}

TEST(SimEnergy, EmptyExactlyAfterDischargeSteps) {
  for (const auto& [d, r, sub] : {std::tuple{285, 100, 2}, std::tuple{285, 100, 1},
                                  std::tuple{10, 3, 5}, std::tuple{1, 1, 2}}) {
    World world(test::empty_arena(0.6, 0.6), energy_robot(d, r, sub));
    world.reset({0.3, 0.3, 0.0});
    EXPECT_EQ(world.state().floor.energy, 1.0);
    for (int i = 1; i < d; ++i) {
      world.step(0.0, 0.0);
      EXPECT_FALSE(world.state().floor.energy_empty) << i;
      // After i steps: (d - i) / d of the charge, as integer units.
      const double full = static_cast<double>(d) * r * sub;
      EXPECT_EQ(world.state().floor.energy, static_cast<double>((d - i) * r * sub) / full) << i;
    }
    EXPECT_GT(world.state().floor.energy, 0.0);
    world.step(0.0, 0.0);
    EXPECT_EQ(world.state().floor.energy, 0.0) << d;
    EXPECT_TRUE(world.state().floor.energy_empty);
    world.step(0.3, 0.3);  // stays empty, clamped at 0
    EXPECT_EQ(world.state().floor.energy, 0.0);
    EXPECT_TRUE(world.state().floor.energy_empty);
    world.reset({0.3, 0.3, 0.0});  // a new epoch starts full
    EXPECT_EQ(world.state().floor.energy, 1.0);
    EXPECT_FALSE(world.state().floor.energy_empty);
  }
}

TEST(SimEnergy, NoDischargeInsideARechargeZone) {
  ArenaSpec a = test::empty_arena(0.6, 0.6);
  a.zones.push_back(circle(0.3, 0.3, 0.1, true));
  World world(a, energy_robot());
  world.reset({0.3, 0.3, 1.0});
  for (int i = 0; i < 1000; ++i) world.step(-1.0, 1.0);  // turning on the spot inside
  EXPECT_EQ(world.state().floor.energy, 1.0);
  // A zone that does not recharge does nothing for the accumulator.
  ArenaSpec b = test::empty_arena(0.6, 0.6);
  b.zones.push_back(circle(0.3, 0.3, 0.1, false));
  World other(b, energy_robot());
  other.reset({0.3, 0.3, 1.0});
  for (int i = 0; i < 285; ++i) other.step(-1.0, 1.0);
  EXPECT_TRUE(other.state().floor.energy_empty);
}

// Drive straight along +x with inertia off: after substep k of driving the centre is at
// x0 + k * v * dt_sub (to ~1e-7 m); the zone edge is placed half a substep between two.
TEST(SimEnergy, RechargesFromEmptyToFullInExactlyRechargeSteps) {
  const double x0 = 0.1;
  const double sub_m = 0.08 * 0.05;  // 4 mm per substep at full speed
  const int approach_steps = 10;
  const double edge = x0 + sub_m * 2 * approach_steps + sub_m / 2;
  ArenaSpec a = test::empty_arena(1.2, 0.6);
  a.zones.push_back(rectangle(edge + 0.45, 0.3, 0.9, 0.2, true));
  World world(a, energy_robot());
  world.reset({x0, 0.3, 0.0});
  for (int i = 0; i < 285; ++i) world.step(0.0, 0.0);
  ASSERT_TRUE(world.state().floor.energy_empty);
  for (int i = 0; i < approach_steps; ++i) world.step(1.0, 1.0);  // to just before the edge
  EXPECT_EQ(world.state().floor.in_zone, 0U);
  EXPECT_EQ(world.state().floor.energy, 0.0);
  for (int i = 1; i < 100; ++i) {
    world.step(1.0, 1.0);
    EXPECT_EQ(world.state().floor.in_zone, 1U);
    EXPECT_FALSE(world.state().floor.energy_empty);
    EXPECT_EQ(world.state().floor.energy, static_cast<double>(i * 2 * 285) / 57000.0) << i;
  }
  EXPECT_LT(world.state().floor.energy, 1.0);
  world.step(1.0, 1.0);
  EXPECT_EQ(world.state().floor.energy, 1.0);
  world.step(0.0, 0.0);  // and stays full
  EXPECT_EQ(world.state().floor.energy, 1.0);
}

// A scripted trajectory in and out of a recharge zone, with settable numbers (7 steps to
// empty, 3 to full, 2 substeps: 42 units, -3 per substep outside, +7 inside), the
// membership of every substep predicted from the straight-line motion.
TEST(SimEnergy, MixedTrajectoryExact) {
  const int D = 7, R = 3, S = 2;
  const std::int64_t full = D * R * S;
  const double x0 = 0.1;
  const double sub_m = 0.08 * 0.1 / S;
  const double lo = x0 + 7 * sub_m + sub_m / 2;  // entered mid-step (substep 8 of driving)
  const double hi = lo + 0.1;
  ArenaSpec a = test::empty_arena(1.0, 0.6);
  a.zones.push_back(rectangle(0.5 * (lo + hi), 0.3, hi - lo, 0.2, true));
  World world(a, energy_robot(D, R, S));
  world.reset({x0, 0.3, 0.0});
  // (command, steps): stand, drive in, stand inside, drive on through and out of the far
  // side, stand outside until empty, drive back in, stand until full.
  const std::vector<std::pair<double, int>> script = {
      {0.0, 3}, {1.0, 6}, {0.0, 1}, {1.0, 14}, {0.0, 4}, {1.0, 4}, {0.0, 12}, {-1.0, 10}, {0.0, 6}};
  std::int64_t units = full;
  int k = 0;  // substeps of displacement so far (forward minus backward)
  for (const auto& [cmd, steps] : script) {
    for (int s = 0; s < steps; ++s) {
      for (int j = 0; j < S; ++j) {
        k += static_cast<int>(cmd);
        const double x = x0 + k * sub_m;
        ASSERT_GT(std::min(std::abs(x - lo), std::abs(x - hi)), 1e-3);  // unambiguous
        const bool inside = x >= lo && x <= hi;
        units = inside ? std::min(full, units + D) : std::max<std::int64_t>(0, units - R);
      }
      world.step(cmd, cmd);
      EXPECT_NEAR(world.state().pose.x_m, x0 + k * sub_m, 1e-6);
      EXPECT_EQ(world.state().floor.energy, static_cast<double>(units) / static_cast<double>(full))
          << "after command " << cmd << ", x = " << world.state().pose.x_m;
      EXPECT_EQ(world.state().floor.energy_empty, units == 0);
    }
  }
  EXPECT_EQ(units, full);  // the script ends back inside, recharged
}

// ---- zones ----------------------------------------------------------------------------

TEST(SimZones, CentreInsideCircleAndRectangle) {
  ArenaSpec a = test::empty_arena(0.6, 0.6);
  a.zones.push_back(circle(0.2, 0.2, 0.05, false, true));   // visible
  a.zones.push_back(rectangle(0.4, 0.3, 0.1, 0.2));          // invisible
  a.zones.push_back(circle(0.45, 0.4, 0.03));                // overlaps the rectangle's corner
  World w(a, RobotParams{});
  const auto at = [&](double x, double y) {
    w.reset({x, y, 0.3});
    return std::pair{w.state().floor.in_zone, w.state().floor.ground};
  };
  EXPECT_EQ(at(0.2, 0.2), std::pair(1U, true));
  EXPECT_EQ(at(0.2 + 0.049, 0.2), std::pair(1U, true));
  EXPECT_EQ(at(0.2 + 0.036, 0.2 + 0.036), std::pair(0U, false));  // 0.0509 from the centre
  EXPECT_EQ(at(0.4, 0.3), std::pair(2U, false));                   // invisible: no ground
  EXPECT_EQ(at(0.449, 0.201), std::pair(2U, false));
  EXPECT_EQ(at(0.451, 0.3), std::pair(0U, false));
  EXPECT_EQ(at(0.4, 0.399), std::pair(2U, false));
  EXPECT_EQ(at(0.4, 0.401), std::pair(0U, false));                 // above the rectangle
  EXPECT_EQ(at(0.46, 0.405), std::pair(4U, false));
  EXPECT_EQ(at(0.44, 0.39), std::pair(6U, false));                 // both
  EXPECT_EQ(at(0.1, 0.5), std::pair(0U, false));
  EXPECT_FALSE(w.in_zone(7, {0.4, 0.3}));   // no such zone
  // Boundaries are included (binary-exact numbers).
  ArenaSpec b = test::empty_arena(0.5, 0.5);
  b.zones.push_back(rectangle(0.25, 0.25, 0.25, 0.125));
  b.zones.push_back(circle(0.25, 0.25, 0.125));
  World wb(b, RobotParams{});
  EXPECT_TRUE(wb.in_zone(0, {0.375, 0.3125}));
  EXPECT_FALSE(wb.in_zone(0, {0.375 + 1e-12, 0.3125}));
  EXPECT_FALSE(wb.in_zone(0, {0.375, 0.3125 + 1e-12}));
  EXPECT_TRUE(wb.in_zone(1, {0.25, 0.125}));
  EXPECT_FALSE(wb.in_zone(1, {0.25, 0.125 - 1e-12}));
  ASSERT_EQ(w.zone_centers().size(), 3U);
  EXPECT_EQ(w.zone_centers()[1].x, 0.4);
}

ArenaSpec random_zone_arena() {
  ArenaSpec a = test::empty_arena(0.6, 0.5);
  a.cylinders.push_back({{0.2, 0.3}, 0.05});
  a.cylinders.push_back({{0.45, 0.15}, 0.03});
  a.boxes.push_back({{0.4, 0.38}, {0.12, 0.03}, 0.5});
  Zone z = circle(0.0, 0.0, 0.06, true);
  z.random_position = true;
  a.zones.push_back(z);
  a.zones.push_back(rectangle(0.1, 0.1, 0.08, 0.06));  // fixed
  Zone r = rectangle(0.0, 0.0, 0.1, 0.05);
  r.random_position = true;
  a.zones.push_back(r);
  LightSource above;
  above.above_zone = 0;
  above.height_m = 0.1;
  a.lights.push_back(above);
  LightSource fixed;
  fixed.position_m = {0.55, 0.45};
  a.lights.push_back(fixed);
  return a;
}

// Ground sensors read the floor at their own points: 1 over a visible zone, 0 over an
// invisible one or bare floor, each turning with the body.
TEST(SimZones, GroundSensorsReadVisibleZonesAtTheirPoints) {
  ArenaSpec a = test::empty_arena(0.6, 0.6);
  a.zones.push_back(rectangle(0.45, 0.3, 0.1, 0.2, false, true));   // visible, x 0.40 .. 0.50
  a.zones.push_back(rectangle(0.15, 0.3, 0.1, 0.2));                // invisible, x 0.10 .. 0.20
  RobotParams robot;
  robot.ground.mounts = {{0.0, 0.025}, {std::numbers::pi, 0.025}};   // 2.5 cm ahead and behind
  World world(a, robot);
  std::array<double, 2> g{};
  const auto read = [&](Pose p) {
    world.reset(p);
    world.read_ground(g);
    return std::pair(g[0], g[1]);
  };
  EXPECT_EQ(read({0.38, 0.3, 0.0}), std::pair(1.0, 0.0));    // the front point at 0.405
  EXPECT_EQ(read({0.38, 0.3, std::numbers::pi}), std::pair(0.0, 1.0));   // turned: the back one
  EXPECT_EQ(read({0.45, 0.3, 0.0}), std::pair(1.0, 1.0));
  EXPECT_EQ(read({0.45, 0.3, std::numbers::pi / 2}), std::pair(1.0, 1.0));   // along the zone
  EXPECT_EQ(read({0.15, 0.3, 0.0}), std::pair(0.0, 0.0));    // invisible
  EXPECT_EQ(read({0.3, 0.1, 0.0}), std::pair(0.0, 0.0));     // bare floor
}

TEST(SimZones, RandomPlacementInsideClearAndDeterministic) {
  const ArenaSpec a = random_zone_arena();
  World w(a, RobotParams{});
  World other(a, RobotParams{});
  // Before any placement a random zone sits at the arena's centre.
  EXPECT_EQ(w.zone_centers()[0].x, 0.3);
  EXPECT_EQ(w.zone_centers()[0].y, 0.25);
  double min_x = 1, max_x = 0;
  for (std::uint64_t seed = 0; seed < 300; ++seed) {
    Rng rng(seed);
    w.place_zones(rng);
    const Vec2 c0 = w.zone_centers()[0];
    const Vec2 c2 = w.zone_centers()[2];
    EXPECT_GE(c0.x, 0.06);
    EXPECT_LE(c0.x, 0.54);
    EXPECT_GE(c0.y, 0.06);
    EXPECT_LE(c0.y, 0.44);
    EXPECT_GE(test::obstacle_clearance(a, c0.x, c0.y), 0.06 - 1e-12);
    EXPECT_GE(c2.x, 0.05);
    EXPECT_LE(c2.x, 0.55);
    EXPECT_GE(c2.y, 0.025);
    EXPECT_LE(c2.y, 0.475);
    EXPECT_GE(test::obstacle_clearance(a, c2.x, c2.y), std::hypot(0.05, 0.025) - 1e-12);
    min_x = std::min(min_x, c0.x);
    max_x = std::max(max_x, c0.x);
    // The fixed zone stays, the light above zone 0 follows it, the other light stays.
    EXPECT_EQ(w.zone_centers()[1].x, 0.1);
    EXPECT_EQ(w.light_positions()[0].x, c0.x);
    EXPECT_EQ(w.light_positions()[0].y, c0.y);
    EXPECT_EQ(w.light_positions()[1].x, 0.55);
    // Membership follows the placed zone.
    w.reset({c0.x, c0.y, 0.0});
    EXPECT_TRUE(w.state().floor.in_zone & 1U);
    // Deterministic per seed, whatever the world did before.
    Rng again(seed);
    other.place_zones(again);
    EXPECT_EQ(other.zone_centers()[0].x, c0.x);
    EXPECT_EQ(other.zone_centers()[2].y, c2.y);
  }
  EXPECT_LT(min_x, 0.1);  // spread over the arena
  EXPECT_GT(max_x, 0.5);
  Rng r1(1), r2(2);
  w.place_zones(r1);
  const Vec2 first = w.zone_centers()[0];
  w.place_zones(r2);
  EXPECT_NE(w.zone_centers()[0].x, first.x);
}

TEST(SimZones, LightAboveARandomZoneMovesItsReading) {
  ArenaSpec a = test::empty_arena(0.6, 0.6);
  Zone z = circle(0, 0, 0.05, true);
  z.random_position = true;
  a.zones.push_back(z);
  LightSource l;
  l.above_zone = 0;
  a.lights.push_back(l);
  World w(a, RobotParams{});
  Rng rng(3);
  std::array<double, kLightSensors> v{};
  for (int i = 0; i < 20; ++i) {
    w.place_zones(rng);
    const Vec2 c = w.zone_centers()[0];
    // Stand 20 cm from the zone's centre facing it (inside the arena when possible).
    const double ang = std::atan2(0.3 - c.y, 0.3 - c.x);
    const Pose p{c.x + 0.1 * std::cos(ang), c.y + 0.1 * std::sin(ang), ang + std::numbers::pi};
    w.reset(p);
    w.read_light(v, rng);
    EXPECT_GT(v[2] + v[3], 1.0) << i;  // bright ahead
    EXPECT_EQ(v[6] + v[7], 0.0);
  }
}

TEST(SimZones, NoDrawWithoutRandomZonesAndBeginEpochOrder) {
  ArenaSpec a = test::empty_arena(0.6, 0.6);
  a.zones.push_back(circle(0.3, 0.3, 0.05));
  World w(a, RobotParams{});
  Rng rng(5);
  Rng copy = rng;
  w.place_zones(rng);
  EXPECT_EQ(rng.next(), copy.next());
  // begin_epoch draws exactly what reset(random_free_pose) draws.
  Rng e1(9), e2(9);
  const Pose p = w.begin_epoch(e1);
  const Pose q = w.random_free_pose(e2);
  EXPECT_EQ(p.x_m, q.x_m);
  EXPECT_EQ(p.heading_rad, q.heading_rad);
  EXPECT_EQ(e1.next(), e2.next());
  EXPECT_EQ(w.state().pose.x_m, p.x_m);
  // With a random zone: zones first, then the pose.
  ArenaSpec b = random_zone_arena();
  World wb(b, RobotParams{});
  Rng f1(11), f2(11);
  const Pose pb = wb.begin_epoch(f1);
  World ref(b, RobotParams{});
  ref.place_zones(f2);
  const Pose qb = ref.random_free_pose(f2);
  EXPECT_EQ(pb.x_m, qb.x_m);
  EXPECT_EQ(wb.zone_centers()[0].x, ref.zone_centers()[0].x);
  // A fixed start wins over a random pose.
  ArenaSpec c = b;
  c.fixed_start = Pose{0.05, 0.05, 1.0};
  World wc(c, RobotParams{});
  Rng g(1);
  EXPECT_EQ(wc.begin_epoch(g).x_m, 0.05);
}

TEST(SimZones, NoFreePlaceThrows) {
  ArenaSpec a = test::empty_arena(0.3, 0.3);
  a.cylinders.push_back({{0.15, 0.15}, 0.14});
  Zone z = circle(0, 0, 0.1);
  z.random_position = true;
  a.zones.push_back(z);
  World w(a, RobotParams{});
  Rng rng(1);
  EXPECT_THROW(w.place_zones(rng), std::runtime_error);
}

// ---- reached(light) ---------------------------------------------------------------------

TEST(SimReached, RisingEdgeCountedOncePerEntry) {
  ArenaSpec a = test::empty_arena(1.0, 0.6);
  LightSource l;
  l.position_m = {0.5, 0.3};
  a.lights.push_back(l);
  LightSource far;
  far.position_m = {0.9, 0.5};
  a.lights.push_back(far);
  RobotParams r;
  r.motor.inertia = false;
  World w(a, r);
  w.reset({0.3, 0.3, 0.0});
  const double reach = a.reach_radius_m;
  int events = 0;
  bool was_inside = false;
  const auto drive = [&](double cmd, int steps) {
    for (int i = 0; i < steps; ++i) {
      w.step(cmd, cmd);
      const bool inside = std::abs(w.state().pose.x_m - 0.5) <= reach;
      const bool edge = inside && !was_inside;
      EXPECT_EQ(w.state().floor.reached, edge ? 1U : 0U) << "x = " << w.state().pose.x_m;
      events += edge ? 1 : 0;
      was_inside = inside;
    }
  };
  drive(1.0, 50);   // through the light's reach and out: one event
  EXPECT_EQ(events, 1);
  EXPECT_EQ(w.state().floor.reach_count[0], 1);
  drive(-1.0, 30);  // back in: a second one
  EXPECT_EQ(events, 2);
  EXPECT_EQ(w.state().floor.reach_count[0], 2);
  drive(0.0, 10);   // staying: none
  EXPECT_EQ(w.state().floor.reach_count[1], 0);
  // Starting within reach is not an event; leaving and returning is.
  w.reset({0.5, 0.3, 0.0});
  EXPECT_EQ(w.state().floor.reached, 0U);
  EXPECT_EQ(w.state().floor.reach_count[0], 0);
  was_inside = true;
  events = 0;
  drive(1.0, 10);
  EXPECT_EQ(events, 0);
  drive(-1.0, 12);
  EXPECT_EQ(events, 1);
  EXPECT_EQ(w.state().floor.reach_count[0], 1);
}

// ---- validation -------------------------------------------------------------------------

void expect_invalid(const ArenaSpec& a, const RobotParams& r, const std::string& field) {
  try {
    World w(a, r);
    ADD_FAILURE() << "no exception for " << field;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
  }
}

TEST(SimZones, InvalidParametersNameTheField) {
  const RobotParams ok;
  ArenaSpec a = test::empty_arena(0.6, 0.6);
  a.zones.push_back(circle(0.58, 0.3, 0.05));
  expect_invalid(a, ok, "arena.zones[0]");
  a.zones[0] = circle(0.3, 0.3, -0.05);
  expect_invalid(a, ok, "arena.zones[0].radius_m");
  a.zones[0] = rectangle(0.3, 0.3, 0.1, 0.0);
  expect_invalid(a, ok, "arena.zones[0].size_m");
  a.zones[0] = circle(0.3, 0.3, 0.4);
  a.zones[0].random_position = true;  // too big to fit anywhere
  expect_invalid(a, ok, "arena.zones[0]");
  a.zones.assign(9, circle(0.3, 0.3, 0.05));
  expect_invalid(a, ok, "arena zone count");
  a.zones.assign(1, circle(0.3, 0.3, 0.05));
  LightSource l;
  l.position_m = {0.7, 0.3};
  a.lights = {l};
  expect_invalid(a, ok, "arena.lights[0].position_m");
  a.lights[0].position_m = {0.3, 0.3};
  a.lights[0].above_zone = 1;
  expect_invalid(a, ok, "arena.lights[0].above_zone");
  a.lights[0].above_zone = -1;
  a.lights[0].intensity = -1;
  expect_invalid(a, ok, "arena.lights[0].intensity");
  a.lights[0].intensity = 1;
  a.lights[0].height_m = std::nan("");
  expect_invalid(a, ok, "arena.lights[0].height_m");
  a.lights.assign(5, LightSource{{0.3, 0.3}, 0.0, 1.0, -1});
  expect_invalid(a, ok, "arena light count");
  a.lights.clear();
  a.sweep_cell_m = 0.0;
  expect_invalid(a, ok, "arena.sweep_cell_m");
  a.sweep_cell_m = 1e-6;
  expect_invalid(a, ok, "arena.sweep_cell_m");
  a.sweep_cell_m = 0.04;
  a.reach_radius_m = -1;
  expect_invalid(a, ok, "arena.reach_radius_m");
  a.reach_radius_m = 0.05;
  RobotParams r;
  r.energy.discharge_steps = 0;
  expect_invalid(a, r, "robot.energy.discharge_steps");
  r = ok;
  r.energy.recharge_steps = -3;
  expect_invalid(a, r, "robot.energy.recharge_steps");
  r = ok;
  r.light.half_distance_m = 0.0;
  expect_invalid(a, r, "robot.light.half_distance_m");
  r = ok;
  r.light.noise_sd = -0.1;
  expect_invalid(a, r, "robot.light.noise_sd");
  EXPECT_NO_THROW(World(a, ok));
}

}  // namespace
}  // namespace esc::sim
