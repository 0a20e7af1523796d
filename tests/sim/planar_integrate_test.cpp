// integrate_planar (runtime/sim/planar_integrate.hpp) gives Bullet's integrateTransform bit
// for bit, for every kind of substep the drive produces: the free-space path of Body::move
// relies on it to leave results unchanged. Calls Bullet directly, so it is a binary of its own.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <numbers>
#include <random>

#include "runtime/sim/planar_integrate.hpp"

namespace esc::sim {
namespace {

constexpr double kWheelBase_m = 0.053;
constexpr double kSubstep_s = 0.05;
constexpr double kTopSpeed_mps = 0.08;

struct Substep {
  btTransform now;
  btVector3 linear, angular;
  PlanarVelocity v;
};

Substep substep(double x_m, double y_m, double heading_rad, double left_mps, double right_mps) {
  Substep s;
  s.now.setIdentity();
  s.now.setOrigin(btVector3(x_m, y_m, 0));
  s.now.setRotation(btQuaternion(btVector3(0, 0, 1), heading_rad));
  const btMatrix3x3& m = s.now.getBasis();
  s.v = DifferentialDrive(kWheelBase_m, kSubstep_s).velocity(left_mps, right_mps, {m[0][0], m[1][0]});
  s.linear = btVector3(s.v.x_mps, s.v.y_mps, 0);
  s.angular = btVector3(0, 0, s.v.turn_radps);
  return s;
}

bool same_bits(const btTransform& a, const btTransform& b) {
  std::array<double, 12> x{}, y{};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      x[static_cast<std::size_t>(3 * r + c)] = a.getBasis()[r][c];
      y[static_cast<std::size_t>(3 * r + c)] = b.getBasis()[r][c];
    }
  for (int i = 0; i < 3; ++i) {
    x[static_cast<std::size_t>(9 + i)] = a.getOrigin()[i];
    y[static_cast<std::size_t>(9 + i)] = b.getOrigin()[i];
  }
  return std::memcmp(x.data(), y.data(), sizeof x) == 0;
}

// Bullet's result and integrate_planar's, for one substep.
void expect_bullet(const Substep& s) {
  btTransform bullet, planar;
  btTransformUtil::integrateTransform(s.now, s.linear, s.angular, kSubstep_s, bullet);
  integrate_planar(s.now, s.linear, s.angular, kSubstep_s, s.v, planar);
  EXPECT_TRUE(same_bits(bullet, planar)) << "turn " << s.v.turn_radps << " rad/s";
}

TEST(SimPlanarIntegrate, IsBulletsIntegrationBitForBitOverRandomSubsteps) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> pos(0.0, 0.6), angle(-std::numbers::pi, std::numbers::pi),
      speed(-kTopSpeed_mps, kTopSpeed_mps);
  for (int i = 0; i < 20000; ++i) expect_bullet(substep(pos(rng), pos(rng), angle(rng), speed(rng), speed(rng)));
}

TEST(SimPlanarIntegrate, IsBulletsIntegrationOnEveryBranch) {
  // Straight (no turn), a turn just below and just above Bullet's Taylor threshold, turns in
  // place both ways, and headings on the axes where the quaternion's components vanish.
  const double tiny = 0.001 * kWheelBase_m;   // wheel speed difference of a 0.001 rad/s turn
  for (const double heading : {0.0, std::numbers::pi / 2, std::numbers::pi, -std::numbers::pi / 2, 1.0, -2.5})
    for (const auto& [l, r] : std::array<std::pair<double, double>, 7>{{{0.05, 0.05},
                                                                        {0.05, 0.05 + 0.99 * tiny},
                                                                        {0.05, 0.05 + 1.01 * tiny},
                                                                        {0.05 + 1.01 * tiny, 0.05},
                                                                        {-kTopSpeed_mps, kTopSpeed_mps},
                                                                        {kTopSpeed_mps, -kTopSpeed_mps},
                                                                        {0.0, 0.0}}})
      expect_bullet(substep(0.3, 0.2, heading, l, r));
}

TEST(SimPlanarIntegrate, TakesTheRotationFromTheDrivesHalfTurn) {
  // The sine and cosine come from the drive's velocity, not from new libm calls: another
  // half turn in `v` gives another rotation (so the bit-for-bit tests above compare them).
  Substep s = substep(0.3, 0.2, 0.4, 0.02, 0.07);
  btTransform bullet, planar;
  btTransformUtil::integrateTransform(s.now, s.linear, s.angular, kSubstep_s, bullet);
  s.v.sin_half_turn = std::sin(2 * std::asin(s.v.sin_half_turn));
  s.v.cos_half_turn = std::cos(2 * std::acos(s.v.cos_half_turn));
  integrate_planar(s.now, s.linear, s.angular, kSubstep_s, s.v, planar);
  EXPECT_FALSE(same_bits(bullet, planar));
  EXPECT_EQ(bullet.getOrigin(), planar.getOrigin());
}

}  // namespace
}  // namespace esc::sim
