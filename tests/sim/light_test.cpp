// Ambient light sensors: the response formula, distance, incidence, occlusion by walls and
// obstacles, intensity, height, saturation and noise.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "sim_test_util.hpp"

namespace esc::sim {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr std::array<double, 8> kMountDeg = {68, 43, 13, -13, -43, -68, 158, -158};
constexpr std::array<double, 8> kFacingDeg = {90, 45, 10, -10, -45, -90, 180, 180};

LightSource light_at(double x, double y, double height = 0.0, double intensity = 1.0) {
  LightSource l;
  l.position_m = {x, y};
  l.height_m = height;
  l.intensity = intensity;
  return l;
}

// The model written out independently: I max(0, cos a) / (1 + (d / d0)^2), unoccluded.
double expected(const RobotParams& r, const Pose& p, std::size_t sensor, const LightSource& l) {
  const double mount = p.heading_rad + kMountDeg[sensor] * kDeg;
  const double facing = p.heading_rad + kFacingDeg[sensor] * kDeg;
  const double sx = p.x_m + r.body_radius_m * std::cos(mount);
  const double sy = p.y_m + r.body_radius_m * std::sin(mount);
  const double ex = l.position_m.x - sx;
  const double ey = l.position_m.y - sy;
  const double d = std::sqrt(ex * ex + ey * ey + l.height_m * l.height_m);
  const double cos_a = (std::cos(facing) * ex + std::sin(facing) * ey) / d;
  if (cos_a <= 0.0) return 0.0;
  const double d0 = r.light.half_distance_m;
  return std::min(1.0, l.intensity * cos_a / (1.0 + (d / d0) * (d / d0)));
}

class SimLight : public ::testing::Test {
 protected:
  RobotParams robot;
  Rng rng{1};

  std::array<double, kLightSensors> read_at(World& w, Pose p) {
    w.reset(p);
    std::array<double, kLightSensors> out{};
    w.read_light(out, rng);
    return out;
  }
};

TEST_F(SimLight, DarkWithoutLights) {
  World world(test::empty_arena(0.6, 0.6), robot);
  for (double v : read_at(world, {0.3, 0.3, 0.4})) EXPECT_EQ(v, 0.0);
}

TEST_F(SimLight, MatchesTheModelAtEverySensor) {
  ArenaSpec arena = test::empty_arena(1.0, 1.0);
  arena.lights.push_back(light_at(0.7, 0.55, 0.03, 0.8));
  World world(arena, robot);
  for (const Pose p : {Pose{0.3, 0.5, 0.0}, Pose{0.6, 0.2, 2.0}, Pose{0.8, 0.8, -1.0},
                       Pose{0.62, 0.55, 0.1}}) {
    const auto v = read_at(world, p);
    for (std::size_t i = 0; i < 8; ++i)
      EXPECT_NEAR(v[i], expected(robot, p, i, arena.lights[0]), 1e-12) << i;
  }
  // Head-on at the half distance: 0.5 of the intensity.
  ArenaSpec a2 = test::empty_arena(1.0, 1.0);
  a2.lights.push_back(light_at(0.5, 0.5));
  World w2(a2, robot);
  // Sensor 2 faces +10 deg from the heading: point it at the light from half_distance away.
  const double facing = 10 * kDeg;
  const double d0 = robot.light.half_distance_m;
  const double sx = 0.5 - d0 * std::cos(0.0);
  const double sy = 0.5;
  // Heading h with sensor 2's facing (h + 10 deg) = 0 and its mount on the line.
  const double h = -facing;
  const Pose p{sx - robot.body_radius_m * std::cos(h + 13 * kDeg),
               sy - robot.body_radius_m * std::sin(h + 13 * kDeg), h};
  EXPECT_NEAR(read_at(w2, p)[2], 0.5, 1e-12);
}

TEST_F(SimLight, FallsMonotonicallyWithDistance) {
  ArenaSpec arena = test::empty_arena(1.2, 0.6);
  arena.lights.push_back(light_at(1.1, 0.3));
  World world(arena, robot);
  std::array<double, kLightSensors> prev{};
  prev.fill(2.0);
  for (int i = 0; i <= 90; ++i) {
    const double x = 1.0 - 0.01 * i;  // heading towards the light, backing away from it
    const auto v = read_at(world, {x, 0.3, 0.0});
    // The sensors facing the light (+-10 deg); the +-45 deg ones first brighten as the
    // incidence improves, then fall too.
    for (std::size_t s : {2U, 3U}) {
      EXPECT_LT(v[s], prev[s]) << "sensor " << s << " at x = " << x;
      EXPECT_GT(v[s], 0.0);
    }
    if (x < 0.9) {
      EXPECT_LT(v[1], prev[1]) << x;
      EXPECT_LT(v[4], prev[4]) << x;
    }
    prev = v;
  }
  EXPECT_LT(prev[2], 0.06);  // 1 m away: dim
}

TEST_F(SimLight, SensorsFacingAwayReadLess) {
  ArenaSpec arena = test::empty_arena(1.0, 1.0);
  arena.lights.push_back(light_at(0.8, 0.5));
  World world(arena, robot);
  const auto v = read_at(world, {0.4, 0.5, 0.0});  // facing the light
  EXPECT_GT(v[2], v[0]);
  EXPECT_GT(v[3], v[5]);
  EXPECT_GT(v[2], v[1]);
  EXPECT_EQ(v[6], 0.0);  // the back pair faces away
  EXPECT_EQ(v[7], 0.0);
  const auto back = read_at(world, {0.4, 0.5, std::numbers::pi});  // turned away
  EXPECT_GT(back[6], 0.0);
  EXPECT_EQ(back[2], 0.0);
  EXPECT_EQ(back[3], 0.0);
  EXPECT_LT(std::max(back[0], back[5]), v[2]);
  // Symmetric about the heading.
  EXPECT_NEAR(v[2], v[3], 1e-15);
  EXPECT_NEAR(v[1], v[4], 1e-15);
}

TEST_F(SimLight, ObstaclesAndWallsOcclude) {
  const Pose p{0.2, 0.3, 0.0};
  ArenaSpec open = test::empty_arena(0.6, 0.6);
  open.lights.push_back(light_at(0.5, 0.3));
  World lit(open, robot);
  const auto bright = read_at(lit, p);
  EXPECT_GT(bright[2], 0.25);

  ArenaSpec walled = open;  // a thin wall across the arena between robot and light
  walled.boxes.push_back({{0.35, 0.3}, {0.01, 0.6}, 0.0});
  World dark(walled, robot);
  for (double v : read_at(dark, p)) EXPECT_EQ(v, 0.0);

  // A thin cylinder shadows sensors 2 and 3 (their lines to the light pass 3.4 mm from its
  // axis) but not 1 and 4 (10 mm).
  ArenaSpec pillar = open;
  pillar.cylinders.push_back({{0.35, 0.3}, 0.008});
  World shadowed(pillar, robot);
  const auto s = read_at(shadowed, p);
  EXPECT_GT(bright[2], 0.0);
  EXPECT_EQ(s[2], 0.0);
  EXPECT_EQ(s[3], 0.0);
  EXPECT_GT(s[1], 0.0);
  EXPECT_EQ(s[1], bright[1]);
  EXPECT_EQ(s[4], bright[4]);

  // A rotated box in the way, and one beside the path that casts no shadow.
  ArenaSpec rotated = open;
  rotated.boxes.push_back({{0.4, 0.3}, {0.05, 0.02}, 0.9});
  World r(rotated, robot);
  const auto rv = read_at(r, p);
  EXPECT_EQ(rv[2], 0.0);
  ArenaSpec beside = open;
  beside.boxes.push_back({{0.4, 0.45}, {0.05, 0.02}, 0.9});
  World b(beside, robot);
  EXPECT_EQ(read_at(b, p), bright);
}

TEST_F(SimLight, IntensityHeightAndSaturation) {
  const Pose p{0.3, 0.3, 0.0};
  ArenaSpec a = test::empty_arena(0.6, 0.6);
  a.lights.push_back(light_at(0.5, 0.3));
  World unit(a, robot);
  const auto base = read_at(unit, p);
  a.lights[0].intensity = 0.5;
  World half(a, robot);
  EXPECT_NEAR(read_at(half, p)[2], 0.5 * base[2], 1e-15);
  a.lights[0].intensity = 1.0;
  a.lights[0].height_m = 0.1;  // higher: farther and more oblique
  World high(a, robot);
  EXPECT_LT(read_at(high, p)[2], base[2]);
  // Close bright lights saturate at 1.
  ArenaSpec sat = test::empty_arena(0.6, 0.6);
  sat.lights.push_back(light_at(0.36, 0.3, 0.0, 3.0));
  sat.lights.push_back(light_at(0.36, 0.31, 0.0, 3.0));
  World s(sat, robot);
  const auto v = read_at(s, p);
  EXPECT_EQ(v[2], 1.0);
  EXPECT_EQ(v[3], 1.0);
  // Two lights add up below saturation.
  ArenaSpec two = test::empty_arena(0.6, 0.6);
  two.lights.push_back(light_at(0.5, 0.3));
  two.lights.push_back(light_at(0.1, 0.3));
  World t(two, robot);
  ArenaSpec other = test::empty_arena(0.6, 0.6);
  other.lights.push_back(light_at(0.1, 0.3));
  World o(other, robot);
  const auto tv = read_at(t, p);
  const auto ov = read_at(o, p);
  for (std::size_t i = 0; i < 8; ++i) EXPECT_NEAR(tv[i], base[i] + ov[i], 1e-15);
}

TEST_F(SimLight, NoiseOnlyWhenConfigured) {
  ArenaSpec a = test::empty_arena(0.6, 0.6);
  a.lights.push_back(light_at(0.5, 0.3));
  const Pose p{0.3, 0.3, 0.0};
  World quiet(a, robot);
  Rng before = rng;
  const auto clean = read_at(quiet, p);
  EXPECT_EQ(rng.next(), before.next());  // no draw without noise

  RobotParams noisy = robot;
  noisy.light.noise_sd = 0.05;
  World loud(a, noisy);
  Rng n1(7), n2(7);
  std::array<double, kLightSensors> v1{}, v2{};
  loud.reset(p);
  loud.read_light(v1, n1);
  loud.read_light(v2, n2);
  EXPECT_EQ(v1, v2);  // same stream, same noise
  int differ = 0;
  for (std::size_t i = 0; i < 8; ++i) {
    EXPECT_GE(v1[i], 0.0);
    EXPECT_LE(v1[i], 1.0);
    differ += v1[i] != clean[i] ? 1 : 0;
  }
  EXPECT_GE(differ, 4);  // dark sensors clamp at 0 half of the time
}

}  // namespace
}  // namespace esc::sim
