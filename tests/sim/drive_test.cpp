// The differential drive on its own (drive.hpp, no Bullet): the velocity it imposes for a
// substep carries the body exactly to the end of the arc that wheels without slip drive.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "runtime/sim/drive.hpp"

namespace esc::sim {
namespace {

constexpr double kWheelBase_m = 0.053;
constexpr double kSubstep_s = 0.05;

Vec2 heading_at(double angle_rad) { return {std::cos(angle_rad), std::sin(angle_rad)}; }

TEST(SimDrive, EqualWheelSpeedsGoStraightAlongTheHeading) {
  const DifferentialDrive drive(kWheelBase_m, kSubstep_s);
  const double angle_rad = 0.7;
  const PlanarVelocity v = drive.velocity(0.06, 0.06, heading_at(angle_rad));
  EXPECT_EQ(v.turn_radps, 0.0);
  EXPECT_NEAR(v.x_mps, 0.06 * std::cos(angle_rad), 1e-17);
  EXPECT_NEAR(v.y_mps, 0.06 * std::sin(angle_rad), 1e-17);
  EXPECT_NEAR(v.travel_m, 0.06 * kSubstep_s, 1e-18);
}

TEST(SimDrive, OppositeWheelSpeedsTurnInPlace) {
  const DifferentialDrive drive(kWheelBase_m, kSubstep_s);
  const PlanarVelocity v = drive.velocity(-0.04, 0.04, heading_at(-2.0));
  EXPECT_EQ(v.x_mps, 0.0);
  EXPECT_EQ(v.y_mps, 0.0);
  EXPECT_EQ(v.travel_m, 0.0);
  EXPECT_DOUBLE_EQ(v.turn_radps, 0.08 / kWheelBase_m);   // counter-clockwise: right wheel faster
}

// Moving at the imposed velocity for dt while turning at w ends where the arc of radius
// R = v / w about the instantaneous centre of rotation ends, for any heading and turn.
TEST(SimDrive, TheImposedVelocityEndsTheSubstepOnTheArc) {
  const DifferentialDrive drive(kWheelBase_m, kSubstep_s);
  for (const double angle_rad : {0.0, 1.1, -2.9}) {
    for (const auto& [left, right] : {std::pair{0.08, 0.02}, std::pair{-0.03, 0.07}, std::pair{0.05, -0.08}}) {
      const PlanarVelocity v = drive.velocity(left, right, heading_at(angle_rad));
      const double speed = 0.5 * (left + right);
      const double w = (right - left) / kWheelBase_m;
      const double radius = speed / w;
      // Centre of rotation to the left of the heading, at distance R.
      const double cx = -radius * std::sin(angle_rad);
      const double cy = radius * std::cos(angle_rad);
      const double end_rad = angle_rad + w * kSubstep_s;
      const double x = cx + radius * std::sin(end_rad);
      const double y = cy - radius * std::cos(end_rad);
      EXPECT_NEAR(v.x_mps * kSubstep_s, x, 1e-15) << left << " " << right << " " << angle_rad;
      EXPECT_NEAR(v.y_mps * kSubstep_s, y, 1e-15) << left << " " << right << " " << angle_rad;
      EXPECT_DOUBLE_EQ(v.turn_radps, w);
      EXPECT_NEAR(v.travel_m, std::hypot(x, y), 1e-15);
    }
  }
}

}  // namespace
}  // namespace esc::sim
