#include "runtime/sim/world.hpp"

#include <BulletCollision/CollisionDispatch/btSphereBoxCollisionAlgorithm.h>
#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <memory>
#include <mutex>
#include <numbers>
#include <stdexcept>
#include <utility>
#include <vector>

#include "runtime/sim/geometry2d.hpp"
#include "runtime/sim/ir_sensor.hpp"
#include "runtime/sim/light_sensor.hpp"
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
// Beyond the body's radius plus a substep's travel plus this, no contact can act on the
// body during the substep: World::Impl::advance integrates it without a Bullet step.
constexpr double kFreeSpaceMargin_m = 0.001;
// Walls are boxes this thick outside the inner rectangle; static shapes are this tall
// (centred on the plane) so every contact normal is horizontal.
constexpr double kWallThickness_m = 0.1;
constexpr double kStaticHeight_m = 0.4;
// Coulomb friction between body and walls (Bullet's default), no restitution.
constexpr btScalar kContactFriction = 0.5F;
constexpr btScalar kRestitution = 0.0F;
// Free-pose and random-zone rejection sampling give up after this many draws.
constexpr int kFreePoseTries = 10000;
// The sweep grid has ceil(size / cell - this) columns (rows), so that a size that is a whole
// number of cells up to rounding (0.6 / 0.04) gets no sliver column.
constexpr double kSweepCellRounding = 1e-9;

// A zone at its position this epoch.
struct ZoneGeom {
  bool circle = true;
  double cx = 0.0, cy = 0.0;
  double r2 = 0.0;          // circle: radius^2
  double hx = 0.0, hy = 0.0;  // half extents (circle: the radius)

  [[nodiscard]] bool contains(double x, double y) const noexcept {
    const double dx = x - cx;
    const double dy = y - cy;
    if (circle) return dx * dx + dy * dy <= r2;
    return std::abs(dx) <= hx && std::abs(dy) <= hy;
  }
};

int grid_count(double size_m, double cell_m) {
  return std::max(1, static_cast<int>(std::ceil(size_m / cell_m - kSweepCellRounding)));
}

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
  LightModel light;
  WheelMotor motor;
  RobotState state;

  // Zones and lights where they are this epoch (place_zones moves the random ones).
  std::vector<ZoneGeom> zones;
  std::vector<Vec2> zone_centers;
  std::uint32_t recharge_mask = 0;  // bit i: zone i recharges
  std::uint32_t visible_mask = 0;   // bit i: zone i is seen by the ground sensor
  std::vector<PlacedLight> lights;
  std::vector<Vec2> light_positions;
  double reach2 = 0.0;              // reach radius^2
  std::uint32_t inside_reach = 0;   // bit i: centre within reach of light i after the last step

  // Energy in integer units: full = discharge * recharge * substeps; each substep outside
  // a recharge zone takes recharge_steps units (discharge_steps * substeps substeps from
  // full to empty), each substep inside gives discharge_steps units.
  bool energy_on = false;
  std::int64_t energy_full = 1;
  std::int64_t energy_units = 1;
  std::int64_t energy_drain = 0;
  std::int64_t energy_gain = 0;

  // Area-sweeping grid, one bit per cell, sized here once.
  int sweep_cols = 1;
  int sweep_rows = 1;
  std::vector<std::uint64_t> visited;

  // Bullet; the dynamics world is declared last so it is destroyed first.
  std::unique_ptr<btDefaultCollisionConfiguration> config;
  std::unique_ptr<btSphereBoxCollisionAlgorithm::CreateFunc> sphere_box, box_sphere;
  std::unique_ptr<btCollisionDispatcher> dispatcher;
  std::unique_ptr<btAxisSweep3> broadphase;
  std::unique_ptr<btSequentialImpulseConstraintSolver> solver;
  std::vector<std::unique_ptr<btCollisionShape>> shapes;
  std::vector<std::unique_ptr<btRigidBody>> statics;
  std::unique_ptr<btSphereShape> body_shape;
  std::unique_ptr<btRigidBody> body;
  std::unique_ptr<btDiscreteDynamicsWorld> world;

  Impl(const ArenaSpec& a, const KheperaParams& r)
      : arena((validate_arena(a), a)),
        robot((validate_robot(r), r)),
        substep_s(r.control_step_s / r.physics_substeps),
        geometry(a),
        ir(r),
        light(r),
        motor(r.motor, substep_s) {
    disable_bullet_profiling();
    set_up_floor();
    config = std::make_unique<btDefaultCollisionConfiguration>();
    dispatcher = std::make_unique<btCollisionDispatcher>(config.get());
    // Bullet's default configuration sends sphere-box pairs to GJK; its closed-form
    // sphere-box algorithm is opt-in.
    sphere_box = std::make_unique<btSphereBoxCollisionAlgorithm::CreateFunc>();
    box_sphere = std::make_unique<btSphereBoxCollisionAlgorithm::CreateFunc>();
    box_sphere->m_swapped = true;
    dispatcher->registerCollisionCreateFunc(SPHERE_SHAPE_PROXYTYPE, BOX_SHAPE_PROXYTYPE, sphere_box.get());
    dispatcher->registerCollisionCreateFunc(BOX_SHAPE_PROXYTYPE, SPHERE_SHAPE_PROXYTYPE, box_sphere.get());
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
    // The body only moves in the plane z = 0, where every static shape is centred, so a
    // sphere meets a wall exactly where the vertical cylinder of the same radius would, and
    // Bullet's sphere-box contact is closed-form (with speculative contacts): no GJK at
    // every substep the robot spends against a wall. (Sphere-sphere contacts are not
    // speculative, so obstacle cylinders stay cylinders, met by GJK.)
    body_shape = std::make_unique<btSphereShape>(bt(r.body_radius_m));
    // The inertia of the body, a solid cylinder, not of the sphere standing in for it.
    btVector3 inertia(0, 0, 0);
    btCylinderShapeZ(btVector3(bt(r.body_radius_m), bt(r.body_radius_m), bt(r.body_height_m / 2)))
        .calculateLocalInertia(bt(r.mass_kg), inertia);
    btRigidBody::btRigidBodyConstructionInfo info(bt(r.mass_kg), nullptr, body_shape.get(), inertia);
    info.m_friction = kContactFriction;
    info.m_restitution = kRestitution;
    body = std::make_unique<btRigidBody>(info);
    body->setLinearFactor(btVector3(1, 1, 0));   // planar: no z motion,
    body->setAngularFactor(btVector3(0, 0, 1));  // rotation about z only
    // It turns about z only: no gyroscopic torque to integrate.
    body->setFlags(body->getFlags() & ~BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY);
    body->setActivationState(DISABLE_DEACTIVATION);
    body->setSleepingThresholds(0, 0);
    world->addRigidBody(body.get());

    warm_up();
    const Pose start = a.fixed_start.value_or(Pose{w / 2, h / 2, 0.0});
    reset(start);
  }

  // Zones at their declared positions (random ones at the arena's centre until
  // place_zones), lights, energy constants and the sweep grid.
  void set_up_floor() {
    const std::size_t nz = arena.zones.size();
    zones.resize(nz);
    zone_centers.resize(nz);
    for (std::size_t i = 0; i < nz; ++i) {
      const Zone& z = arena.zones[i];
      ZoneGeom& g = zones[i];
      g.circle = z.shape == ZoneShape::Circle;
      g.hx = g.circle ? z.radius_m : 0.5 * z.size_m.x;
      g.hy = g.circle ? z.radius_m : 0.5 * z.size_m.y;
      g.r2 = z.radius_m * z.radius_m;
      const Vec2 c = z.random_position ? Vec2{arena.width_m / 2, arena.height_m / 2} : z.center_m;
      g.cx = c.x;
      g.cy = c.y;
      zone_centers[i] = c;
      if (z.recharge) recharge_mask |= 1U << i;
      if (z.visible) visible_mask |= 1U << i;
    }
    lights.resize(arena.lights.size());
    light_positions.resize(arena.lights.size());
    for (std::size_t l = 0; l < arena.lights.size(); ++l) {
      lights[l].height_m = arena.lights[l].height_m;
      lights[l].intensity = arena.lights[l].intensity;
    }
    place_lights();
    reach2 = arena.reach_radius_m * arena.reach_radius_m;
    energy_on = robot.energy.enabled;
    energy_drain = robot.energy.recharge_steps;
    energy_gain = robot.energy.discharge_steps;
    energy_full = static_cast<std::int64_t>(robot.energy.discharge_steps) *
                  robot.energy.recharge_steps * robot.physics_substeps;
    energy_units = energy_full;
    sweep_cols = grid_count(arena.width_m, arena.sweep_cell_m);
    sweep_rows = grid_count(arena.height_m, arena.sweep_cell_m);
    const auto cells = static_cast<std::size_t>(sweep_cols) * static_cast<std::size_t>(sweep_rows);
    visited.assign((cells + 63) / 64, 0);
  }

  // Lights above a zone stand at its centre; the others where the arena says.
  void place_lights() {
    for (std::size_t l = 0; l < arena.lights.size(); ++l) {
      const LightSource& src = arena.lights[l];
      const Vec2 p = src.above_zone >= 0 ? zone_centers[static_cast<std::size_t>(src.above_zone)]
                                         : src.position_m;
      lights[l].x_m = p.x;
      lights[l].y_m = p.y;
      light_positions[l] = p;
    }
  }

  void place_zones(Rng& rng) {
    bool moved = false;
    for (std::size_t i = 0; i < arena.zones.size(); ++i) {
      if (!arena.zones[i].random_position) continue;
      ZoneGeom& g = zones[i];
      // Clear of obstacles: a circle exactly, a rectangle by its circumscribed circle.
      const double keep = g.circle ? std::sqrt(g.r2) : std::hypot(g.hx, g.hy);
      bool placed = false;
      for (int t = 0; t < kFreePoseTries && !placed; ++t) {
        const double x = rng.uniform(g.hx, arena.width_m - g.hx);
        const double y = rng.uniform(g.hy, arena.height_m - g.hy);
        if (geometry.obstacle_clearance({x, y}, keep) >= keep) {
          g.cx = x;
          g.cy = y;
          zone_centers[i] = {x, y};
          placed = true;
        }
      }
      if (!placed)
        throw std::runtime_error("arena.zones[" + std::to_string(i) +
                                 "] has no free place: no position found that keeps it inside "
                                 "the arena and clear of every obstacle");
      moved = true;
    }
    if (moved) place_lights();
  }

  [[nodiscard]] bool in_recharge(double x, double y) const noexcept {
    for (std::uint32_t m = recharge_mask; m != 0; m &= m - 1)
      if (zones[static_cast<std::size_t>(std::countr_zero(m))].contains(x, y)) return true;
    return false;
  }

  // The floor-related state at the robot's current pose: zones, ground, reach edges,
  // visited cells, energy level. `fresh`: the start of an epoch.
  void observe_floor(bool fresh) {
    const double x = state.pose.x_m;
    const double y = state.pose.y_m;
    std::uint32_t in = 0;
    for (std::size_t i = 0; i < zones.size(); ++i)
      if (zones[i].contains(x, y)) in |= 1U << i;
    state.in_zone = in;
    state.ground = (in & visible_mask) != 0;
    std::uint32_t near = 0;
    for (std::size_t l = 0; l < lights.size(); ++l) {
      const double dx = x - lights[l].x_m;
      const double dy = y - lights[l].y_m;
      if (dx * dx + dy * dy <= reach2) near |= 1U << l;
    }
    state.reached = fresh ? 0U : near & ~inside_reach;
    for (std::uint32_t m = state.reached; m != 0; m &= m - 1)
      ++state.reach_count[static_cast<std::size_t>(std::countr_zero(m))];
    inside_reach = near;
    const double cell_m = arena.sweep_cell_m;
    const int col = std::clamp(static_cast<int>(std::floor(x / cell_m)), 0, sweep_cols - 1);
    const int row = std::clamp(static_cast<int>(std::floor(y / cell_m)), 0, sweep_rows - 1);
    const auto cell = static_cast<std::size_t>(row) * static_cast<std::size_t>(sweep_cols) +
                      static_cast<std::size_t>(col);
    const std::uint64_t bit = std::uint64_t{1} << (cell % 64);
    std::uint64_t& word = visited[cell / 64];
    state.new_cell = (word & bit) == 0 && !fresh;
    if ((word & bit) == 0) {
      word |= bit;
      ++state.cells_visited;
    }
    state.energy = energy_units == energy_full
                       ? 1.0
                       : static_cast<double>(energy_units) / static_cast<double>(energy_full);
    state.energy_empty = energy_on && energy_units == 0;
  }

  // Grows Bullet's internal arrays (pair cache, manifolds, islands, solver pools) to the
  // size of the robot touching every static object at once, so step() never allocates:
  // a body as large as the arena steps a few times in contact with everything, then the
  // real body takes its place (reset() removes every trace but the capacities).
  void warm_up() {
    const double half_diagonal = 0.5 * std::hypot(arena.width_m, arena.height_m) + kWallThickness_m;
    btSphereShape big(bt(half_diagonal));
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
    energy_units = energy_full;
    std::fill(visited.begin(), visited.end(), std::uint64_t{0});
    observe_floor(true);
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
      advance(std::abs(chord) * substep_s);
      const btVector3& p = body->getWorldTransform().getOrigin();
      if (geometry.clearance({p.x(), p.y()}, contact_reach) <= contact_reach) collided = true;
      if (energy_on) {
        energy_units = in_recharge(p.x(), p.y())
                           ? std::min(energy_full, energy_units + energy_gain)
                           : std::max(std::int64_t{0}, energy_units - energy_drain);
      }
    }
    state.wheel_speed_mps[0] = vl;
    state.wheel_speed_mps[1] = vr;
    state.pose = body_pose();
    const double ddx = state.pose.x_m - x0;
    const double ddy = state.pose.y_m - y0;
    state.displacement_m = std::hypot(ddx, ddy);
    state.forward_displacement_m = (ddx * hx0 + ddy * hy0) / std::hypot(hx0, hy0);
    state.collided = collided;
    observe_floor(false);
  }

  // One substep of Bullet at the imposed velocities, the body moving `travel_m`. Far from
  // every surface no contact can push it (a speculative contact acts only on a body that
  // would reach the surface within the step), and a Bullet step of a lone body without
  // gravity or damping is exactly its transform integrated at the given velocities: that
  // is done here, with Bullet's own integrator, without the collision detection, islands
  // and solver of a full step (2.5-3x the control steps/s of the paper's workloads). While
  // any contact point is still cached (up to 2 cm from a surface) Bullet steps, so that
  // its solver's warm start sees every step it would have seen. Results stay deterministic;
  // against stepping Bullet every substep they differ in the last digits only (about 1e-8
  // relative on a short run's fitness: the broadphase, updated less often, may list the
  // contact pairs in another order).
  void advance(double travel_m) {
    const btVector3& p = body->getWorldTransform().getOrigin();
    const double keep = robot.body_radius_m + travel_m + kFreeSpaceMargin_m;
    if (has_contact_points() || geometry.clearance({p.x(), p.y()}, keep) <= keep) {
      world->stepSimulation(bt(substep_s), 0, bt(substep_s));
      return;
    }
    btTransform next;
    btTransformUtil::integrateTransform(body->getWorldTransform(), body->getLinearVelocity(),
                                        body->getAngularVelocity(), bt(substep_s), next);
    body->proceedToTransform(next);
  }

  [[nodiscard]] bool has_contact_points() const {
    const int n = dispatcher->getNumManifolds();
    for (int i = 0; i < n; ++i)
      if (dispatcher->getManifoldByIndexInternal(i)->getNumContacts() > 0) return true;
    return false;
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
void World::place_zones(Rng& rng) { impl_->place_zones(rng); }
void World::reset(const Pose& pose) { impl_->reset(pose); }
Pose World::begin_epoch(Rng& rng) {
  impl_->place_zones(rng);
  const Pose pose = impl_->arena.fixed_start ? *impl_->arena.fixed_start
                                             : random_free_pose(rng);
  impl_->reset(pose);
  return pose;
}
void World::step(double left_command, double right_command) {
  impl_->step(left_command, right_command);
}
void World::read_ir(std::array<double, kIrSensors>& out, Rng& rng) const {
  impl_->ir.read(impl_->state.pose, impl_->geometry, out, rng);
}
void World::read_light(std::array<double, kLightSensors>& out, Rng& rng) const {
  impl_->light.read(impl_->state.pose, impl_->geometry, impl_->lights.data(),
                    impl_->lights.size(), out, rng);
}
std::span<const Vec2> World::zone_centers() const noexcept { return impl_->zone_centers; }
std::span<const Vec2> World::light_positions() const noexcept { return impl_->light_positions; }
bool World::in_zone(std::size_t zone, Vec2 p) const noexcept {
  return zone < impl_->zones.size() && impl_->zones[zone].contains(p.x, p.y);
}
int World::sweep_columns() const noexcept { return impl_->sweep_cols; }
int World::sweep_rows() const noexcept { return impl_->sweep_rows; }
const RobotState& World::state() const noexcept { return impl_->state; }
const KheperaParams& World::robot() const noexcept { return impl_->robot; }
const ArenaSpec& World::arena() const noexcept { return impl_->arena; }

}  // namespace esc::sim
