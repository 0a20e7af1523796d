#pragma once
// Bullet's integrateTransform for the Khepera's body, which turns about z only, reusing the
// sine and cosine of the half turn that the drive computed for the same substep (drive.hpp).
// The free-space path of Body::move integrates every substep far from surfaces this way: the
// result is Bullet's bit for bit (tests/sim/planar_integrate_test.cpp), for two libm calls
// fewer per substep. Includes Bullet: internal to esc_sim and the tests that link Bullet.
#include <btBulletDynamicsCommon.h>

#include <cmath>

#include "runtime/sim/drive.hpp"

namespace esc::sim {

// btTransformUtil::integrateTransform(now, linear, angular, dt_s, next) for `angular` along z
// and `v` the drive's velocity of which `angular` is the turn. Bullet takes the sine and
// cosine of |w| dt / 2; the drive took them of w dt / 2 (the same value up to its sign: the
// halving is exact), and sin is odd, cos even, so they are the same doubles. Where Bullet
// takes another branch (a turn below 0.001 rad/s: a Taylor series; beyond an eighth of a
// turn per substep: clamped) Bullet's own function runs.
inline void integrate_planar(const btTransform& now, const btVector3& linear, const btVector3& angular, btScalar dt_s,
                             const PlanarVelocity& v, btTransform& next) {
  const btScalar turn_radps = angular.z();
  const btScalar angle_radps = std::abs(turn_radps);
  if (angular.x() != 0 || angular.y() != 0 || angle_radps < btScalar(0.001) ||
      angle_radps * dt_s > ANGULAR_MOTION_THRESHOLD) {
    btTransformUtil::integrateTransform(now, linear, angular, dt_s, next);
    return;
  }
  next.setOrigin(now.getOrigin() + linear * dt_s);
  const btScalar axis_z = turn_radps * (static_cast<btScalar>(std::abs(v.sin_half_turn)) / angle_radps);
  btQuaternion turned = btQuaternion(0, 0, axis_z, static_cast<btScalar>(v.cos_half_turn)) * now.getRotation();
  turned.safeNormalize();
  if (turned.length2() > SIMD_EPSILON)
    next.setRotation(turned);
  else
    next.setBasis(now.getBasis());
}

}  // namespace esc::sim
