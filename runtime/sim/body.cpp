#include "runtime/sim/body.hpp"

#include "runtime/sim/outline.hpp"

#include <cmath>
#include <mutex>
#include <numbers>
#include <utility>

namespace esc::sim {

namespace {

// Collision margin of every Bullet shape (inside the shape's outer surface, so the
// surfaces are exact); small against the 27.5 mm body, large enough for robust GJK.
constexpr btScalar kCollisionMargin_m = 0.0005F;
// Walls are boxes this thick outside the inner rectangle; static shapes are this tall
// (centred on the plane) so every contact normal is horizontal.
constexpr double kWallThickness_m = 0.1;
constexpr double kStaticHeight_m = 0.4;
// Coulomb friction between body and walls (Bullet's default), no restitution.
constexpr btScalar kContactFriction = 0.5F;
constexpr btScalar kRestitution = 0.0F;

void no_profile_enter(const char*) {}
void no_profile_leave() {}

// Bullet's BT_PROFILE scopes read the clock about twenty times per step; switch them off.
void disable_bullet_profiling() {
  static std::once_flag once;
  std::call_once(once, [] {
    btSetCustomEnterProfileZoneFunc(&no_profile_enter);
    btSetCustomLeaveProfileZoneFunc(&no_profile_leave);
  });
}

btScalar bt(double v) { return static_cast<btScalar>(v); }

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

Body::Body(const ArenaSpec& a, const RobotParams& r, double substep_s, const StaticGeometry2D& geometry)
    : radius_m_(r.body_radius_m), substep_s_(substep_s), max_travel_m_(r.motor.max_speed_mps * substep_s),
      geometry_(geometry) {
  disable_bullet_profiling();
  config_ = std::make_unique<btDefaultCollisionConfiguration>();
  dispatcher_ = std::make_unique<btCollisionDispatcher>(config_.get());
  // Bullet's default configuration sends sphere-box pairs to GJK; its closed-form
  // sphere-box algorithm is opt-in.
  sphere_box_ = std::make_unique<btSphereBoxCollisionAlgorithm::CreateFunc>();
  box_sphere_ = std::make_unique<btSphereBoxCollisionAlgorithm::CreateFunc>();
  box_sphere_->m_swapped = true;
  dispatcher_->registerCollisionCreateFunc(SPHERE_SHAPE_PROXYTYPE, BOX_SHAPE_PROXYTYPE, sphere_box_.get());
  dispatcher_->registerCollisionCreateFunc(BOX_SHAPE_PROXYTYPE, SPHERE_SHAPE_PROXYTYPE, box_sphere_.get());
  // Manifolds keep points up to gContactBreakingThreshold (0.02 m) apart, not a
  // fraction of the body size, so the solver sees a wall before the body reaches it.
  dispatcher_->setDispatcherFlags(dispatcher_->getDispatcherFlags() &
                                  ~btCollisionDispatcher::CD_USE_RELATIVE_CONTACT_BREAKING_THRESHOLD);
  const double pad = kWallThickness_m + 1.0;
  const auto handles = static_cast<unsigned short>(a.boxes.size() + a.walls.size() + a.cylinders.size() + 8);
  // Sweep and prune: its state after removing and re-adding the body depends only on
  // where the objects are, which place() relies on. No ray accelerator (no Bullet rays).
  broadphase_ = std::make_unique<btAxisSweep3>(btVector3(bt(-pad), bt(-pad), bt(-kStaticHeight_m)),
                                               btVector3(bt(a.width_m + pad), bt(a.height_m + pad),
                                                         bt(kStaticHeight_m)),
                                               handles, nullptr, true);
  solver_ = std::make_unique<btSequentialImpulseConstraintSolver>();
  world_ = std::make_unique<btDiscreteDynamicsWorld>(dispatcher_.get(), broadphase_.get(), solver_.get(),
                                                     config_.get());
  world_->setGravity(btVector3(0, 0, 0));
  world_->setForceUpdateAllAabbs(false);  // static AABBs never change

  const double w = a.width_m;
  const double h = a.height_m;
  const double t = kWallThickness_m;
  add_static_box(-t / 2, h / 2, t / 2, h / 2 + t, 0.0);       // left
  add_static_box(w + t / 2, h / 2, t / 2, h / 2 + t, 0.0);    // right
  add_static_box(w / 2, -t / 2, w / 2 + t, t / 2, 0.0);       // bottom
  add_static_box(w / 2, h + t / 2, w / 2 + t, t / 2, 0.0);    // top
  for (const BoxObstacle& b : a.boxes)
    add_static_box(b.center_m.x, b.center_m.y, b.size_m.x / 2, b.size_m.y / 2, b.angle_rad);
  // A segment wall is its rectangle, the box the 2D geometry holds for it.
  for (const WallSegment& segment : a.walls) {
    const BoxObstacle b = wall_box(segment);
    add_static_box(b.center_m.x, b.center_m.y, b.size_m.x / 2, b.size_m.y / 2, b.angle_rad);
  }
  for (const CylinderObstacle& c : a.cylinders) {
    auto shape = std::make_unique<btCylinderShapeZ>(btVector3(bt(c.radius_m), bt(c.radius_m), bt(kStaticHeight_m / 2)));
    shape->setMargin(kCollisionMargin_m);
    add_static(std::move(shape), c.center_m.x, c.center_m.y, 0.0);
  }

  // The body, added last so its broadphase handle and unique id are the same after
  // every remove-and-add in place().
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
  world_->addRigidBody(body_.get());

  warm_up(a, r);
}

Body::~Body() = default;

// Grows Bullet's internal arrays (pair cache, manifolds, islands, solver pools) to the
// size of the robot touching every static object at once, so a step never allocates:
// a body as large as the arena steps a few times in contact with everything, then the
// real body takes its place (place() removes every trace but the capacities).
void Body::warm_up(const ArenaSpec& arena, const RobotParams& robot) {
  const double half_diagonal = 0.5 * std::hypot(arena.width_m, arena.height_m) + kWallThickness_m;
  // The body's own kind of shape, so that its own contact algorithms are the ones grown.
  const std::unique_ptr<btConvexShape> big =
      outline_.empty() ? std::unique_ptr<btConvexShape>(std::make_unique<btSphereShape>(bt(half_diagonal)))
                       : outline_hull(outline_, robot.body_height_m, half_diagonal / robot.body_radius_m);
  world_->removeRigidBody(body_.get());
  body_->setCollisionShape(big.get());
  btTransform tr;
  tr.setIdentity();
  tr.setOrigin(btVector3(bt(arena.width_m / 2), bt(arena.height_m / 2), 0));
  body_->setCenterOfMassTransform(tr);
  world_->addRigidBody(body_.get());
  constexpr int kWarmUpSteps = 8;
  for (int i = 0; i < kWarmUpSteps; ++i) {
    const double angle = 2 * std::numbers::pi * i / kWarmUpSteps;
    body_->setLinearVelocity(btVector3(bt(0.01 * std::cos(angle)), bt(0.01 * std::sin(angle)), 0));
    body_->setAngularVelocity(btVector3(0, 0, 1));
    world_->stepSimulation(bt(substep_s_), 0, bt(substep_s_));
  }
  world_->removeRigidBody(body_.get());
  body_->setCollisionShape(body_shape_.get());
  world_->addRigidBody(body_.get());
}

void Body::add_static_box(double cx, double cy, double hx, double hy, double angle_rad) {
  auto shape = std::make_unique<btBoxShape>(btVector3(bt(hx), bt(hy), bt(kStaticHeight_m / 2)));
  shape->setMargin(kCollisionMargin_m);
  add_static(std::move(shape), cx, cy, angle_rad);
}

void Body::add_static(std::unique_ptr<btCollisionShape> shape, double x, double y, double angle_rad) {
  btTransform tr;
  tr.setIdentity();
  tr.setOrigin(btVector3(bt(x), bt(y), 0));
  tr.setRotation(btQuaternion(btVector3(0, 0, 1), bt(angle_rad)));
  btRigidBody::btRigidBodyConstructionInfo info(0, nullptr, shape.get());
  info.m_startWorldTransform = tr;
  info.m_friction = kContactFriction;
  info.m_restitution = kRestitution;
  auto rb = std::make_unique<btRigidBody>(info);
  world_->addRigidBody(rb.get());
  shapes_.push_back(std::move(shape));
  statics_.push_back(std::move(rb));
}

double Body::placed_outline_clearance() noexcept {
  place_points(outline_, pose(), placed_);
  return geometry_.clearance(placed_, max_sweep_m_ + 2 * kFreeSpaceMargin_m);
}

void Body::place(const Pose& pose) {
  // Removing the body drops its broadphase pairs, contact manifolds and cached contact
  // algorithms; adding it back rebuilds its sweep-and-prune handle in the same slot.
  world_->removeRigidBody(body_.get());
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
  world_->addRigidBody(body_.get());
  solver_->reset();
  solver_->setRandSeed(0);
  inertia_stale_ = false;
  update_clearance();
}

}  // namespace esc::sim
