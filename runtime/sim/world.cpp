#include "runtime/sim/world.hpp"

#include <btBulletDynamicsCommon.h>

#include <cmath>
#include <memory>
#include <mutex>
#include <numbers>
#include <stdexcept>
#include <utility>
#include <vector>

#include "runtime/sim/geometry2d.hpp"
#include "runtime/sim/ir_sensor.hpp"
#include "runtime/sim/motor.hpp"
#include "runtime/sim/validate.hpp"

namespace esc::sim {

namespace {

// Contact: the body is "in collision" when its 2D clearance to a wall or obstacle is at
// most this (the contact solver stops it at clearance ~0).
constexpr double kContactTolerance_m = 1e-4;
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
// Free-pose rejection sampling gives up after this many draws.
constexpr int kFreePoseTries = 10000;

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

}  // namespace

struct World::Impl {
  ArenaSpec arena;
  KheperaParams robot;
  double substep_s;
  StaticGeometry2D geometry;
  IrModel ir;
  WheelMotor motor;
  RobotState state;

  // Bullet; the dynamics world is declared last so it is destroyed first.
  std::unique_ptr<btDefaultCollisionConfiguration> config;
  std::unique_ptr<btCollisionDispatcher> dispatcher;
  std::unique_ptr<btAxisSweep3> broadphase;
  std::unique_ptr<btSequentialImpulseConstraintSolver> solver;
  std::vector<std::unique_ptr<btCollisionShape>> shapes;
  std::vector<std::unique_ptr<btRigidBody>> statics;
  std::unique_ptr<btCylinderShapeZ> body_shape;
  std::unique_ptr<btRigidBody> body;
  std::unique_ptr<btDiscreteDynamicsWorld> world;

  Impl(const ArenaSpec& a, const KheperaParams& r)
      : arena((validate_arena(a), a)),
        robot((validate_robot(r), r)),
        substep_s(r.control_step_s / r.physics_substeps),
        geometry(a),
        ir(r),
        motor(r.motor, substep_s) {
    disable_bullet_profiling();
    config = std::make_unique<btDefaultCollisionConfiguration>();
    dispatcher = std::make_unique<btCollisionDispatcher>(config.get());
    // Manifolds keep points up to gContactBreakingThreshold (0.02 m) apart, not a
    // fraction of the body size, so the solver sees a wall before the body reaches it.
    dispatcher->setDispatcherFlags(dispatcher->getDispatcherFlags() &
                                   ~btCollisionDispatcher::CD_USE_RELATIVE_CONTACT_BREAKING_THRESHOLD);
    const double pad = kWallThickness_m + 1.0;
    const auto handles = static_cast<unsigned short>(a.boxes.size() + a.cylinders.size() + 8);
    // Sweep and prune: its state after removing and re-adding the body depends only on
    // where the objects are, which reset() relies on. No ray accelerator (no Bullet rays).
    broadphase = std::make_unique<btAxisSweep3>(btVector3(bt(-pad), bt(-pad), bt(-kStaticHeight_m)),
                                                btVector3(bt(a.width_m + pad), bt(a.height_m + pad),
                                                          bt(kStaticHeight_m)),
                                                handles, nullptr, true);
    solver = std::make_unique<btSequentialImpulseConstraintSolver>();
    world = std::make_unique<btDiscreteDynamicsWorld>(dispatcher.get(), broadphase.get(),
                                                      solver.get(), config.get());
    world->setGravity(btVector3(0, 0, 0));
    world->setForceUpdateAllAabbs(false);  // static AABBs never change

    const double w = a.width_m;
    const double h = a.height_m;
    const double t = kWallThickness_m;
    add_static_box(-t / 2, h / 2, t / 2, h / 2 + t, 0.0);       // left
    add_static_box(w + t / 2, h / 2, t / 2, h / 2 + t, 0.0);    // right
    add_static_box(w / 2, -t / 2, w / 2 + t, t / 2, 0.0);       // bottom
    add_static_box(w / 2, h + t / 2, w / 2 + t, t / 2, 0.0);    // top
    for (const BoxObstacle& b : a.boxes)
      add_static_box(b.center_m.x, b.center_m.y, b.size_m.x / 2, b.size_m.y / 2, b.angle_rad);
    for (const CylinderObstacle& c : a.cylinders) {
      auto shape = std::make_unique<btCylinderShapeZ>(
          btVector3(bt(c.radius_m), bt(c.radius_m), bt(kStaticHeight_m / 2)));
      shape->setMargin(kCollisionMargin_m);
      add_static(std::move(shape), c.center_m.x, c.center_m.y, 0.0);
    }

    // The body, added last so its broadphase handle and unique id are the same after
    // every remove-and-add in reset().
    body_shape = std::make_unique<btCylinderShapeZ>(
        btVector3(bt(r.body_radius_m), bt(r.body_radius_m), bt(r.body_height_m / 2)));
    body_shape->setMargin(kCollisionMargin_m);
    btVector3 inertia(0, 0, 0);
    body_shape->calculateLocalInertia(bt(r.mass_kg), inertia);
    btRigidBody::btRigidBodyConstructionInfo info(bt(r.mass_kg), nullptr, body_shape.get(), inertia);
    info.m_friction = kContactFriction;
    info.m_restitution = kRestitution;
    body = std::make_unique<btRigidBody>(info);
    body->setLinearFactor(btVector3(1, 1, 0));   // planar: no z motion,
    body->setAngularFactor(btVector3(0, 0, 1));  // rotation about z only
    body->setActivationState(DISABLE_DEACTIVATION);
    body->setSleepingThresholds(0, 0);
    world->addRigidBody(body.get());

    warm_up();
    const Pose start = a.fixed_start.value_or(Pose{w / 2, h / 2, 0.0});
    reset(start);
  }

  // Grows Bullet's internal arrays (pair cache, manifolds, islands, solver pools) to the
  // size of the robot touching every static object at once, so step() never allocates:
  // a body as large as the arena steps a few times in contact with everything, then the
  // real body takes its place (reset() removes every trace but the capacities).
  void warm_up() {
    const double half_diagonal = 0.5 * std::hypot(arena.width_m, arena.height_m) + kWallThickness_m;
    btCylinderShapeZ big(btVector3(bt(half_diagonal), bt(half_diagonal), bt(robot.body_height_m / 2)));
    big.setMargin(kCollisionMargin_m);
    world->removeRigidBody(body.get());
    body->setCollisionShape(&big);
    btTransform tr;
    tr.setIdentity();
    tr.setOrigin(btVector3(bt(arena.width_m / 2), bt(arena.height_m / 2), 0));
    body->setCenterOfMassTransform(tr);
    world->addRigidBody(body.get());
    constexpr int kWarmUpSteps = 8;
    for (int i = 0; i < kWarmUpSteps; ++i) {
      const double angle = 2 * std::numbers::pi * i / kWarmUpSteps;
      body->setLinearVelocity(btVector3(bt(0.01 * std::cos(angle)), bt(0.01 * std::sin(angle)), 0));
      body->setAngularVelocity(btVector3(0, 0, 1));
      world->stepSimulation(bt(substep_s), 0, bt(substep_s));
    }
    world->removeRigidBody(body.get());
    body->setCollisionShape(body_shape.get());
    world->addRigidBody(body.get());
  }

  void add_static_box(double cx, double cy, double hx, double hy, double angle) {
    auto shape = std::make_unique<btBoxShape>(btVector3(bt(hx), bt(hy), bt(kStaticHeight_m / 2)));
    shape->setMargin(kCollisionMargin_m);
    add_static(std::move(shape), cx, cy, angle);
  }

  void add_static(std::unique_ptr<btCollisionShape> shape, double x, double y, double angle) {
    btTransform tr;
    tr.setIdentity();
    tr.setOrigin(btVector3(bt(x), bt(y), 0));
    tr.setRotation(btQuaternion(btVector3(0, 0, 1), bt(angle)));
    btRigidBody::btRigidBodyConstructionInfo info(0, nullptr, shape.get());
    info.m_startWorldTransform = tr;
    info.m_friction = kContactFriction;
    info.m_restitution = kRestitution;
    auto rb = std::make_unique<btRigidBody>(info);
    world->addRigidBody(rb.get());
    shapes.push_back(std::move(shape));
    statics.push_back(std::move(rb));
  }

  [[nodiscard]] Pose body_pose() const {
    const btTransform& tr = body->getWorldTransform();
    const btMatrix3x3& m = tr.getBasis();
    return {static_cast<double>(tr.getOrigin().x()), static_cast<double>(tr.getOrigin().y()),
            std::atan2(static_cast<double>(m[1][0]), static_cast<double>(m[0][0]))};
  }

  void reset(const Pose& pose) {
    // Removing the body drops its broadphase pairs, contact manifolds and cached contact
    // algorithms; adding it back rebuilds its sweep-and-prune handle in the same slot.
    world->removeRigidBody(body.get());
    btTransform tr;
    tr.setIdentity();
    tr.setOrigin(btVector3(bt(pose.x_m), bt(pose.y_m), 0));
    tr.setRotation(btQuaternion(btVector3(0, 0, 1), bt(pose.heading_rad)));
    body->setLinearVelocity(btVector3(0, 0, 0));
    body->setAngularVelocity(btVector3(0, 0, 0));
    body->clearForces();
    body->setCenterOfMassTransform(tr);  // also the interpolation transform and velocities
    body->setHitFraction(1);
    body->setDeactivationTime(0);
    world->addRigidBody(body.get());
    solver->reset();
    solver->setRandSeed(0);
    state = RobotState{};
    state.pose = body_pose();
  }

  void step(double left_command, double right_command) {
    const double target_l = motor.target(left_command);
    const double target_r = motor.target(right_command);
    const btTransform& tr = body->getWorldTransform();
    const double x0 = tr.getOrigin().x();
    const double y0 = tr.getOrigin().y();
    const double hx0 = tr.getBasis()[0][0];
    const double hy0 = tr.getBasis()[1][0];
    const double inv_wheel_base = 1.0 / robot.wheel_base_m;
    const double contact_reach = robot.body_radius_m + kContactTolerance_m;
    double vl = state.wheel_speed_mps[0];
    double vr = state.wheel_speed_mps[1];
    bool collided = false;
    for (int i = 0; i < robot.physics_substeps; ++i) {
      vl = motor.step(vl, target_l);
      vr = motor.step(vr, target_r);
      // Wheels do not slip: over the substep the body follows the arc of speed v and turn
      // rate w exactly; its chord is v dt sin(w dt/2) / (w dt/2) long along the heading
      // turned by w dt/2. Impose that velocity, let Bullet integrate it (rotation by the
      // exponential map, exact) and stop the body at walls and obstacles.
      const btMatrix3x3& basis = body->getWorldTransform().getBasis();
      const double v = 0.5 * (vl + vr);
      const double w = (vr - vl) * inv_wheel_base;
      const double half_turn = 0.5 * w * substep_s;
      const double chord = half_turn == 0.0 ? v : v * std::sin(half_turn) / half_turn;
      const double c = std::cos(half_turn);
      const double s = std::sin(half_turn);
      const double hx = basis[0][0];
      const double hy = basis[1][0];
      body->setLinearVelocity(btVector3(bt(chord * (c * hx - s * hy)), bt(chord * (s * hx + c * hy)), 0));
      body->setAngularVelocity(btVector3(0, 0, bt(w)));
      world->stepSimulation(bt(substep_s), 0, bt(substep_s));
      const btVector3& p = body->getWorldTransform().getOrigin();
      if (geometry.clearance({p.x(), p.y()}, contact_reach) <= contact_reach) collided = true;
    }
    state.wheel_speed_mps[0] = vl;
    state.wheel_speed_mps[1] = vr;
    state.pose = body_pose();
    const double ddx = state.pose.x_m - x0;
    const double ddy = state.pose.y_m - y0;
    state.displacement_m = std::hypot(ddx, ddy);
    state.forward_displacement_m = (ddx * hx0 + ddy * hy0) / std::hypot(hx0, hy0);
    state.collided = collided;
  }

  [[nodiscard]] Pose random_free_pose(Rng& rng, double margin_m) const {
    const double keep = robot.body_radius_m + margin_m;
    if (2 * keep < arena.width_m && 2 * keep < arena.height_m) {
      for (int i = 0; i < kFreePoseTries; ++i) {
        const double x = rng.uniform(keep, arena.width_m - keep);
        const double y = rng.uniform(keep, arena.height_m - keep);
        if (geometry.clearance({x, y}, keep) >= keep)
          return {x, y, rng.uniform(-std::numbers::pi, std::numbers::pi)};
      }
    }
    throw std::runtime_error(
        "the arena has no free space for the robot (no pose found that keeps the body " +
        std::to_string(margin_m) + " m clear of every wall and obstacle)");
  }
};

World::World(const ArenaSpec& arena, const KheperaParams& robot)
    : impl_(std::make_unique<Impl>(arena, robot)) {}
World::~World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

Pose World::random_free_pose(Rng& rng, double margin_m) const {
  return impl_->random_free_pose(rng, margin_m);
}
void World::reset(const Pose& pose) { impl_->reset(pose); }
void World::step(double left_command, double right_command) {
  impl_->step(left_command, right_command);
}
void World::read_ir(std::array<double, kIrSensors>& out, Rng& rng) const {
  impl_->ir.read(impl_->state.pose, impl_->geometry, out, rng);
}
const RobotState& World::state() const noexcept { return impl_->state; }
const KheperaParams& World::robot() const noexcept { return impl_->robot; }
const ArenaSpec& World::arena() const noexcept { return impl_->arena; }

}  // namespace esc::sim
