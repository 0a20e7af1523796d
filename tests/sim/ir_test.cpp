// IR proximity sensors: the curve, its range, the side each index looks at, noise.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <utility>

#include "runtime/sim/ir_sensor.hpp"
#include "sim_test_util.hpp"

namespace esc::sim {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// Enki's Khepera curve, x in cm, written out here independently of the library.
double enki(double d_m) {
  const double x = d_m * 100.0;
  const double m = 1200.0, x0 = -0.9, c = 7.0;
  return m * (c - x0 * x0) / (x * x - 2 * x0 * x + c);
}
double expected_reading(double d_m, double range_m) {
  if (d_m >= range_m) return 0.0;
  return (enki(d_m) - enki(range_m)) / (enki(0.0) - enki(range_m));
}

class SimIr : public ::testing::Test {
 protected:
  RobotParams robot;  // defaults: range 5 cm, 3 rays over 30 deg, no noise
  ArenaSpec arena = test::empty_arena(1.0, 1.0);
  Rng rng{1};

  std::array<double, kIrSensors> read_at(World& w, Pose p) {
    w.reset(p);
    std::array<double, kIrSensors> out{};
    w.read_ir(out, rng);
    return out;
  }
};

TEST_F(SimIr, CurveEndsAtOneAndZero) {
  EXPECT_DOUBLE_EQ(expected_reading(0.0, robot.ir.range_m), 1.0);
  EXPECT_DOUBLE_EQ(expected_reading(robot.ir.range_m, robot.ir.range_m), 0.0);
}

TEST_F(SimIr, ReadingsRiseMonotonicallyApproachingAWallHeadOn) {
  World world(arena, robot);
  const double r = robot.body_radius_m;
  double prev2 = -1.0, prev3 = -1.0;
  for (int i = 0; i <= 70; ++i) {
    const double gap = 0.07 - 0.001 * i;  // from the body front to the wall at x = 1
    const auto ir = read_at(world, {1.0 - r - gap, 0.5, 0.0});
    if (gap > robot.ir.range_m) {
      for (double v : ir) EXPECT_EQ(v, 0.0) << "gap " << gap;
    }
    EXPECT_GE(ir[2], prev2);
    EXPECT_GE(ir[3], prev3);
    if (gap < robot.ir.range_m - 0.002) {
      EXPECT_GT(ir[2], prev2);
    }
    EXPECT_NEAR(ir[2], ir[3], 1e-6);  // symmetric about the heading
    prev2 = ir[2];
    prev3 = ir[3];
  }
  EXPECT_GT(prev2, 0.95);  // touching
}

TEST_F(SimIr, FollowsTheCurveAtKnownDistances) {
  World world(arena, robot);
  const double r = robot.body_radius_m;
  const double half_aperture = robot.ir.aperture_rad / 2;
  for (double gap : {0.002, 0.01, 0.02, 0.03, 0.04}) {
    const double x = 1.0 - r - gap;
    const auto ir = read_at(world, {x, 0.5, 0.0});
    const double px = static_cast<double>(static_cast<float>(x));  // Bullet stores floats
    // Sensor 2: mounted at 13 deg facing 10 deg; its ray nearest the wall normal is at
    // 10 - 15 = -5 deg.
    const double d2 = (1.0 - px - r * std::cos(13 * kDeg)) / std::cos(10 * kDeg - half_aperture);
    EXPECT_NEAR(ir[2], expected_reading(d2, robot.ir.range_m), 1e-5) << gap;
    // Sensor 1: mounted at 43 deg facing 45 deg, nearest ray at 30 deg.
    const double d1 = (1.0 - px - r * std::cos(43 * kDeg)) / std::cos(45 * kDeg - half_aperture);
    EXPECT_NEAR(ir[1], expected_reading(d1, robot.ir.range_m), 1e-5) << gap;
    EXPECT_NEAR(ir[4], ir[1], 1e-5);
    // Side and back sensors face away from the wall.
    EXPECT_EQ(ir[6], 0.0);
    EXPECT_EQ(ir[7], 0.0);
  }
}

TEST_F(SimIr, SensorIndicesMapToTheDocumentedSides) {
  World world(arena, robot);
  const double r = robot.body_radius_m;
  const double gap = 0.01;
  // Wall on the left (top wall, heading +x): sensor 0 (mount 68, facing 90) sees it.
  auto ir = read_at(world, {0.5, 1.0 - r - gap, 0.0});
  const double d0 = 1.0 - static_cast<double>(static_cast<float>(1.0 - r - gap)) - r * std::sin(68 * kDeg);
  EXPECT_NEAR(ir[0], expected_reading(d0, robot.ir.range_m), 1e-5);
  EXPECT_GT(ir[0], 0.3);
  EXPECT_EQ(ir[5], 0.0);
  EXPECT_EQ(ir[3], 0.0);
  // Wall on the right (bottom wall): sensor 5 lights, not 0.
  ir = read_at(world, {0.5, r + gap, 0.0});
  EXPECT_NEAR(ir[5], expected_reading(d0, robot.ir.range_m), 1e-5);
  EXPECT_EQ(ir[0], 0.0);
  // Wall behind (left wall, x = 0): the back sensors 6 and 7 (mount +-158, facing 180).
  ir = read_at(world, {r + gap, 0.5, 0.0});
  const double d6 = static_cast<double>(static_cast<float>(r + gap)) + r * std::cos(158 * kDeg);
  EXPECT_NEAR(ir[6], expected_reading(d6, robot.ir.range_m), 1e-5);
  EXPECT_NEAR(ir[7], ir[6], 1e-6);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(ir[static_cast<std::size_t>(i)], 0.0) << i;
  // Rotating the robot rotates what it sees: heading +90 deg towards the top wall.
  ir = read_at(world, {0.5, 1.0 - r - gap, std::numbers::pi / 2});
  EXPECT_GT(ir[2], 0.3);
  EXPECT_GT(ir[3], 0.3);
  EXPECT_EQ(ir[0], 0.0);
  EXPECT_EQ(ir[5], 0.0);
}

TEST_F(SimIr, SeesObstacles) {
  arena.cylinders.push_back({{0.5, 0.5}, 0.02});
  arena.boxes.push_back({{0.2, 0.2}, {0.1, 0.04}, std::numbers::pi / 4});
  World world(arena, robot);
  const double r = robot.body_radius_m;
  double prev = -1.0;
  for (double gap : {0.06, 0.04, 0.03, 0.02, 0.01, 0.0}) {
    // Cylinder straight ahead: the front pair sees it equally.
    const auto ir = read_at(world, {0.5 - 0.02 - r - gap, 0.5, 0.0});
    EXPECT_NEAR(ir[2], ir[3], 1e-6);
    EXPECT_GT(ir[2], prev);
    prev = ir[2];
    if (gap > robot.ir.range_m) {
      EXPECT_EQ(ir[2], 0.0);
    }
  }
  // Rotated box ahead along its diagonal normal: gap 1 cm from the face.
  const double n = std::sqrt(0.5);
  const double face = 0.02 + r + 0.01;  // box half-width 2 cm plus body plus gap
  const auto ir = read_at(world, {0.2 - n * face, 0.2 + n * face, -std::numbers::pi / 4});
  EXPECT_GT(ir[2], 0.3);
  EXPECT_NEAR(ir[2], ir[3], 1e-4);
  EXPECT_EQ(ir[6], 0.0);
}

TEST_F(SimIr, NoiseIsDrawnOnlyWhenConfigured) {
  World quiet(arena, robot);
  Rng a(5), b(5);
  std::array<double, kIrSensors> out{};
  quiet.reset({0.5, 0.5, 0.0});
  quiet.read_ir(out, a);
  EXPECT_EQ(a.next(), b.next());  // no draw at noise_sd = 0

  robot.ir.noise_sd = 0.05;
  World noisy(arena, robot);
  const double r = robot.body_radius_m;
  noisy.reset({1.0 - r - 0.02, 0.5, 0.0});
  quiet.reset({1.0 - r - 0.02, 0.5, 0.0});
  std::array<double, kIrSensors> clean{};
  quiet.read_ir(clean, a);
  double sum_sq = 0.0;
  const int reads = 2000;
  for (int i = 0; i < reads; ++i) {
    noisy.read_ir(out, a);
    for (double v : out) {
      EXPECT_GE(v, 0.0);
      EXPECT_LE(v, 1.0);
    }
    sum_sq += (out[2] - clean[2]) * (out[2] - clean[2]);
  }
  EXPECT_NEAR(std::sqrt(sum_sq / reads), robot.ir.noise_sd, 0.005);  // not clamped there
}

// The layout is data: a robot with three sensors reads three, the slots after them stay 0,
// and a mount's distance from the centre moves where its rays start.
TEST_F(SimIr, AMountListIsTheRobotsSensors) {
  robot.ir.mounts = {{0.0, 0.0, std::nullopt}, {90 * kDeg, 90 * kDeg, std::nullopt}, {0.0, 0.0, 0.01}};
  World world(arena, robot);
  const double r = robot.body_radius_m;
  const double gap = 0.02;
  const double px = static_cast<double>(static_cast<float>(1.0 - r - gap));
  const auto ir = read_at(world, {1.0 - r - gap, 0.5, 0.0});
  // Straight ahead, the fan's middle ray meets the wall first (1.0 - px - r away); the same
  // sensor mounted 1 cm from the centre sees it r - 1 cm further.
  EXPECT_NEAR(ir[0], expected_reading(1.0 - px - r, robot.ir.range_m), 1e-5);
  EXPECT_NEAR(ir[2], expected_reading(1.0 - px - 0.01, robot.ir.range_m), 1e-5);
  EXPECT_LT(ir[2], ir[0]);
  EXPECT_EQ(ir[1], 0.0);   // looks at the far side wall
  for (std::size_t i = 3; i < ir.size(); ++i) EXPECT_EQ(ir[i], 0.0) << i;
}

// The Khepera's rim mounts, written out with their radius, read exactly what the default reads.
TEST_F(SimIr, AMountOnTheRimAtItsRadiusReadsAsTheDefault) {
  World rim(arena, robot);
  for (IrMount& m : robot.ir.mounts) m.radius_m = robot.body_radius_m;
  World explicit_radius(arena, robot);
  for (const Pose& p : {Pose{0.95, 0.5, 0.3}, Pose{0.05, 0.04, 2.0}, Pose{0.5, 0.97, 1.5}})
    EXPECT_EQ(read_at(rim, p), read_at(explicit_radius, p));
}

// Enki's curve for another robot (the e-puck's x0 0.3 cm, c 0.7 cm2): flat at its peak below
// x0, as Enki holds F = m there, then falling to 0 at the range.
TEST(SimIrResponse, EnkisCurveIsOneUpToItsPeak) {
  IrParams ir;
  ir.range_m = 0.12;
  ir.curve_x0_cm = 0.3;
  ir.curve_c_cm2 = 0.7;
  const IrResponse response(ir);
  const auto f = [](double x_cm) { return (0.7 - 0.09) / (x_cm * x_cm - 0.6 * x_cm + 0.7); };
  EXPECT_DOUBLE_EQ(response(0.0), 1.0);
  EXPECT_DOUBLE_EQ(response(0.002), 1.0);
  EXPECT_DOUBLE_EQ(response(0.003), 1.0);
  for (double d_cm : {0.5, 1.0, 2.0, 4.0, 8.0})
    EXPECT_NEAR(response(d_cm / 100), (f(d_cm) - f(12.0)) / (1.0 - f(12.0)), 1e-12) << d_cm;
  EXPECT_EQ(response(0.12), 0.0);
}

// The e-puck's sensor 2 (Enki: at (0, -3.3 cm), facing -90 deg, its curve) with a wall on the
// robot's right reads docs/robot-model.md's table for the e-puck: the response at the
// distance from the sensor, whose middle ray meets the wall square on.
TEST(SimIrEpuck, AWallSquareOnReadsTheDocumentedResponse) {
  RobotParams puck;
  puck.body_radius_m = 0.037;
  puck.wheel_base_m = 0.053;
  puck.ir.range_m = 0.12;
  puck.ir.curve_x0_cm = 0.3;
  puck.ir.curve_c_cm2 = 0.7;
  puck.ir.mounts = {{-90 * kDeg, -90 * kDeg, 0.033}};
  World world(test::empty_arena(1.0, 1.0), puck);
  Rng rng(1);
  for (const auto& [d_cm, documented] : {std::pair{0.5, 0.938}, {1.0, 0.553}, {2.0, 0.171}, {4.0, 0.038}, {8.0, 0.006}}) {
    world.reset({0.5, 0.033 + d_cm / 100, 0.0});
    std::array<double, kIrSensors> out{};
    world.read_ir(out, rng);
    EXPECT_NEAR(out[0], documented, 6e-4) << d_cm << " cm";
  }
}

// A measured curve: linear between its points, flat before the first and after the last,
// 0 at and beyond the range.
TEST(SimIrResponse, AMeasuredTableIsInterpolated) {
  IrParams ir;
  ir.range_m = 0.05;
  ir.response = {{0.005, 0.9}, {0.02, 0.5}, {0.04, 0.1}};
  const IrResponse response(ir);
  EXPECT_DOUBLE_EQ(response(0.0), 0.9);
  EXPECT_DOUBLE_EQ(response(0.005), 0.9);
  EXPECT_NEAR(response(0.0125), 0.7, 1e-12);
  EXPECT_NEAR(response(0.03), 0.3, 1e-12);
  EXPECT_DOUBLE_EQ(response(0.045), 0.1);
  EXPECT_EQ(response(0.05), 0.0);
}

}  // namespace
}  // namespace esc::sim
