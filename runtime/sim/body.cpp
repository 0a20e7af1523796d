#include "runtime/sim/body.hpp"

#include "runtime/sim/outline.hpp"

#include <cmath>
#include <numbers>
#include <utility>

namespace esc::sim {

namespace {

// The outline (counter-clockwise) as a prism of the body's height, `scale` times its size in
// the plane: Bullet's hull of its inset, which Bullet's margin grows back to the outline.
std::unique_ptr<btConvexShape> outline_hull(const std::vector<Vec2>& ccw, double height_m, double scale) {
  auto hull = std::make_unique<btConvexHullShape>();
  const double half = height_m / 2 - kCollisionMargin_m;
  for (const Vec2& v : inset(ccw, kCollisionMargin_m / scale))
    for (const double z : {-half, half}) hull->addPoint(btVector3(bt(scale * v.x), bt(scale * v.y), bt(z)), false);
  hull->setMargin(kCollisionMargin_m);
  hull->recalcLocalAabb();
  return hull;
}

}  // namespace

Body::Body(const ArenaSpec& a, const RobotParams& r, double substep_s, const StaticGeometry2D& geometry,
           BulletWorld& bullet)
    : radius_m_(r.body_radius_m), substep_s_(substep_s), max_travel_m_(r.motor.max_speed_mps * substep_s),
      geometry_(geometry), bullet_(bullet) {
  // The body, added after the statics (and the bodies before it) so its broadphase handle and
  // unique id are the same after every take_out and put_back.
  btVector3 inertia(0, 0, 0);
  if (r.outline.empty()) {
    // The body only moves in the plane z = 0, where every static shape is centred, so a
    // sphere meets a wall exactly where the vertical cylinder of the same radius would, and
    // Bullet's sphere-box contact is closed-form (with speculative contacts): no GJK at
    // every substep the robot spends against a wall. (Sphere-sphere contacts are not
    // speculative, so obstacle cylinders stay cylinders, met by GJK.)
    body_shape_ = std::make_unique<btSphereShape>(bt(r.body_radius_m));
    // The inertia of the body, a solid cylinder, not of the sphere standing in for it.
    btCylinderShapeZ(btVector3(bt(r.body_radius_m), bt(r.body_radius_m), bt(r.body_height_m / 2)))
        .calculateLocalInertia(bt(r.mass_kg), inertia);
  } else {
    outline_ = counter_clockwise(r.outline);
    placed_.resize(outline_.size());
    // Both wheels at full speed, opposite ways: the fastest turn.
    max_sweep_m_ = max_travel_m_ + 2 * r.motor.max_speed_mps / r.wheel_base_m * substep_s * r.body_radius_m;
    body_shape_ = outline_hull(outline_, r.body_height_m, 1.0);
    // A uniform plate of the outline turning about the wheels' axle (the body's origin, where
    // Bullet puts the mass); x and y never turn.
    const btScalar iz = bt(r.mass_kg * polar_gyration_sq(outline_));
    inertia = btVector3(iz, iz, iz);
  }
  btRigidBody::btRigidBodyConstructionInfo info(bt(r.mass_kg), nullptr, body_shape_.get(), inertia);
  info.m_friction = kContactFriction;
  info.m_restitution = kRestitution;
  body_ = std::make_unique<btRigidBody>(info);
  body_->setLinearFactor(btVector3(1, 1, 0));   // planar: no z motion,
  body_->setAngularFactor(btVector3(0, 0, 1));  // rotation about z only
  // It turns about z only: no gyroscopic torque to integrate.
  body_->setFlags(body_->getFlags() & ~BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY);
  body_->setActivationState(DISABLE_DEACTIVATION);
  body_->setSleepingThresholds(0, 0);
  bullet_.world().addRigidBody(body_.get());

  warm_up(a, r);
}

Body::~Body() { bullet_.world().removeRigidBody(body_.get()); }

// Grows Bullet's internal arrays (pair cache, manifolds, islands, solver pools) to the
// size of the robot touching every static object at once, so a step never allocates:
// a body as large as the arena steps a few times in contact with everything, then the
// real body takes its place (placing it removes every trace but the capacities).
void Body::warm_up(const ArenaSpec& arena, const RobotParams& robot) {
  const double half_diagonal = 0.5 * std::hypot(arena.width_m, arena.height_m) + kWallThickness_m;
  // The body's own kind of shape, so that its own contact algorithms are the ones grown.
  const std::unique_ptr<btConvexShape> big =
      outline_.empty() ? std::unique_ptr<btConvexShape>(std::make_unique<btSphereShape>(bt(half_diagonal)))
                       : outline_hull(outline_, robot.body_height_m, half_diagonal / robot.body_radius_m);
  bullet_.world().removeRigidBody(body_.get());
  body_->setCollisionShape(big.get());
  btTransform tr;
  tr.setIdentity();
  tr.setOrigin(btVector3(bt(arena.width_m / 2), bt(arena.height_m / 2), 0));
  body_->setCenterOfMassTransform(tr);
  bullet_.world().addRigidBody(body_.get());
  constexpr int kWarmUpSteps = 8;
  for (int i = 0; i < kWarmUpSteps; ++i) {
    const double angle = 2 * std::numbers::pi * i / kWarmUpSteps;
    body_->setLinearVelocity(btVector3(bt(0.01 * std::cos(angle)), bt(0.01 * std::sin(angle)), 0));
    body_->setAngularVelocity(btVector3(0, 0, 1));
    bullet_.step(substep_s_);
  }
  bullet_.world().removeRigidBody(body_.get());
  body_->setCollisionShape(body_shape_.get());
  bullet_.world().addRigidBody(body_.get());
}

double Body::placed_outline_clearance() noexcept {
  place_points(outline_, pose(), placed_);
  return geometry_.clearance(placed_, max_sweep_m_ + 2 * kFreeSpaceMargin_m);
}

void Body::take_out() {
  // Removing the body drops its broadphase pairs, contact manifolds and cached contact
  // algorithms; adding it back (put_back) rebuilds its sweep-and-prune handle in the same slot.
  bullet_.world().removeRigidBody(body_.get());
}

void Body::put_back(const Pose& pose) {
  btTransform tr;
  tr.setIdentity();
  tr.setOrigin(btVector3(bt(pose.x_m), bt(pose.y_m), 0));
  tr.setRotation(btQuaternion(btVector3(0, 0, 1), bt(pose.heading_rad)));
  body_->setLinearVelocity(btVector3(0, 0, 0));
  body_->setAngularVelocity(btVector3(0, 0, 0));
  body_->clearForces();
  body_->setCenterOfMassTransform(tr);  // also the interpolation transform and velocities
  body_->setHitFraction(1);
  body_->setDeactivationTime(0);
  bullet_.world().addRigidBody(body_.get());
  inertia_stale_ = false;
}

}  // namespace esc::sim
