#pragma once
// A robot's rigid body (a disc, or a convex outline: outline.hpp) in the arena's Bullet world
// (bullet_world.hpp): its shape, one substep of motion at an imposed velocity, the contact
// test against walls and obstacles, and its placing (take_out, put_back), which with the
// world's solver reset returns the whole Bullet state to what a fresh world holds so that
// nothing leaks from one evaluation into the next. Internal to esc_sim: it includes Bullet,
// which only esc_sim's sources see (in the precision esc_sim links); World (world.hpp) keeps
// it behind its pimpl.
#include <cmath>
#include <memory>
#include <span>
#include <vector>

#include "runtime/sim/arena.hpp"
#include "runtime/sim/bullet_world.hpp"
#include "runtime/sim/outline.hpp"
#include "runtime/sim/drive.hpp"
#include "runtime/sim/geometry2d.hpp"
#include "runtime/sim/robot_params.hpp"
#include "runtime/sim/planar_integrate.hpp"

namespace esc::sim {

// Contact: the body is "in collision" when its 2D clearance to a wall or obstacle is at
// most this (the contact solver stops it at clearance ~0).
inline constexpr double kContactTolerance_m = 1e-4;
// Beyond the body's radius plus a substep's travel plus this, no contact can act on the
// body during the substep: it is integrated without a Bullet step (Body::integrate).
inline constexpr double kFreeSpaceMargin_m = 0.001;

// The step loop's calls (the substep's, touching, pose, position, heading) are defined here,
// inline, so that the compiler sees them inside World's step as it did when they were one
// function.
class Body {
 public:
  // `geometry` is the arena's and `bullet` the world the body moves in (its own, or the one a
  // group of bodies shares); both must outlive the body. Bullet's arrays are grown here to
  // their working size, so nothing allocates afterwards; place the body before moving it.
  Body(const ArenaSpec& arena, const RobotParams& robot, double substep_s, const StaticGeometry2D& geometry,
       BulletWorld& bullet);
  ~Body();
  // Bullet's objects point at each other.
  Body(const Body&) = delete;
  Body& operator=(const Body&) = delete;

  // Placing the bodies of a world: each taken out of Bullet's world, the last first, then each
  // put back at rest at its pose, the first first, with no contact, broadphase pair or cached
  // contact algorithm left from before; then the world's solver is reset
  // (BulletWorld::reset_solver) and each body's clearance updated. Bullet's world then holds
  // what a freshly built one with the bodies at those poses would: the same objects in the same
  // order (Bullet removes an object by moving its last one into its place), each body in its
  // own broadphase handle.
  void take_out();
  void put_back(const Pose& pose);

  // One physics substep at the velocity `v` (drive.hpp), in three calls: set_velocity, then
  // either a Bullet step of the world (after prepare_bullet_step) or integrate, then
  // update_clearance. Walls, obstacles and other bodies stop the body. Far from every surface
  // no contact can push the body (a speculative contact acts only on a body that would reach
  // the surface within the step), and a Bullet step of a lone body without gravity or damping
  // is exactly its transform integrated at the given velocities: that is integrate(), with
  // Bullet's own integrator, without the collision detection,
  // islands and solver of a full step (2.5-3x the control steps/s of the paper's workloads).
  // While any contact point is still cached (up to 2 cm from a surface) Bullet steps, so
  // that its solver's warm start sees every step it would have seen. Results stay
  // deterministic; against stepping Bullet every substep they differ in the last digits only
  // (about 1e-8 relative on a short run's fitness: the broadphase, updated less often, may
  // list the contact pairs in another order).
  // set_velocity returns whether the body is near a wall or obstacle: whether this substep
  // needs Bullet's step for it.
  bool set_velocity(const PlanarVelocity& v) noexcept {
    body_->setLinearVelocity(btVector3(static_cast<btScalar>(v.x_mps), static_cast<btScalar>(v.y_mps), 0));
    body_->setAngularVelocity(btVector3(0, 0, static_cast<btScalar>(v.turn_radps)));
    const double keep = radius_m_ + v.travel_m + kFreeSpaceMargin_m;
    // An outline's points sweep at most the centre's travel plus the turn at the circle.
    return clearance_m_ <= keep &&
           (outline_.empty() || outline_clearance_m_ <= v.travel_m + std::abs(v.turn_radps) * substep_s_ * radius_m_ +
                                                            kFreeSpaceMargin_m);
  }
  // Before a Bullet step: the solver reads the world inertia tensor, which integrate()
  // leaves behind.
  void prepare_bullet_step() noexcept {
    if (inertia_stale_) body_->updateInertiaTensor();
    inertia_stale_ = false;
  }
  void integrate(const PlanarVelocity& v) noexcept {
    btTransform next;
    integrate_planar(body_->getWorldTransform(), body_->getLinearVelocity(), body_->getAngularVelocity(),
                     static_cast<btScalar>(substep_s_), v, next);
    // btRigidBody::proceedToTransform(next) but for the world inertia tensor, a function of the
    // orientation alone that only the solver reads: it is brought up to date before a step.
    body_->setInterpolationWorldTransform(next);
    body_->setInterpolationLinearVelocity(body_->getLinearVelocity());
    body_->setInterpolationAngularVelocity(body_->getAngularVelocity());
    body_->setWorldTransform(next);
    inertia_stale_ = true;
  }
  // The clearance at the body's position, exact up to the farthest any substep's test looks
  // (radius, a substep's longest travel, the margin): each substep computes it once, for its
  // own contact test and the next substep's free-space test.
  void update_clearance() noexcept {
    const double cutoff_m = radius_m_ + max_travel_m_ + 2 * kFreeSpaceMargin_m;
    clearance_m_ = geometry_.clearance(position(), cutoff_m);
    if (outline_.empty()) {
      touching_ = clearance_m_ <= radius_m_ + kContactTolerance_m;
      return;
    }
    // An outline comes near a surface only where its circle does: its own distance only then.
    outline_clearance_m_ = clearance_m_ <= cutoff_m ? placed_outline_clearance() : StaticGeometry2D::kNoHit;
    touching_ = outline_clearance_m_ <= kContactTolerance_m;
  }

  // The body's robot index, by which BulletWorld::for_each_body_contact names it (the arena's
  // statics have none).
  void set_index(std::size_t robot) noexcept { body_->setUserIndex(static_cast<int>(robot)); }
  // The outline placed at the current pose (counter-clockwise, in the arena's frame), for other
  // robots' rays; empty for a disc.
  [[nodiscard]] std::span<const Vec2> placed_outline() noexcept {
    if (!outline_.empty()) place_points(outline_, pose(), placed_);
    return placed_;
  }

  // Whether the body touches a wall or an obstacle (its clearance is at most
  // kContactTolerance_m; the contact solver stops it at about 0).
  [[nodiscard]] bool touching() const noexcept { return touching_; }
  // Where it touches: the point of the walls and obstacles nearest to the body
  // (geometry2d.hpp). Meaningful while touching(), when an outline is placed at the pose.
  [[nodiscard]] Vec2 contact_point() const noexcept {
    return outline_.empty() ? geometry_.nearest_point(position()) : geometry_.nearest_point(placed_);
  }

  [[nodiscard]] Pose pose() const noexcept {
    const btTransform& tr = body_->getWorldTransform();
    const btMatrix3x3& m = tr.getBasis();
    return {static_cast<double>(tr.getOrigin().x()), static_cast<double>(tr.getOrigin().y()),
            std::atan2(static_cast<double>(m[1][0]), static_cast<double>(m[0][0]))};
  }
  [[nodiscard]] Vec2 position() const noexcept {
    const btVector3& p = body_->getWorldTransform().getOrigin();
    return {p.x(), p.y()};
  }
  // Unit vector along the heading.
  [[nodiscard]] Vec2 heading() const noexcept {
    const btMatrix3x3& m = body_->getWorldTransform().getBasis();
    return {m[0][0], m[1][0]};
  }

 private:
  void warm_up(const ArenaSpec& arena, const RobotParams& robot);
  // The outline's distance at the current position, exact up to the farthest a substep sweeps it.
  [[nodiscard]] double placed_outline_clearance() noexcept;

  double radius_m_;
  double substep_s_;
  double max_travel_m_;          // the top wheel speed over a substep
  const StaticGeometry2D& geometry_;
  double clearance_m_ = 0.0;     // at the current position (update_clearance)
  bool touching_ = false;        // at the current position (update_clearance)
  std::vector<Vec2> outline_;    // counter-clockwise, in the body's frame; empty: a disc
  std::vector<Vec2> placed_;     // the outline at the current position, while near a surface
  double outline_clearance_m_ = 0.0;   // its distance to the walls and obstacles (update_clearance)
  double max_sweep_m_ = 0.0;     // the farthest a point of the outline moves in a substep
  bool inertia_stale_ = false;   // the world inertia tensor is of an earlier orientation

  BulletWorld& bullet_;
  std::unique_ptr<btConvexShape> body_shape_;   // a sphere, or the outline's hull
  std::unique_ptr<btRigidBody> body_;
};

}  // namespace esc::sim
