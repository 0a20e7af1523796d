#pragma once
// The Khepera's rigid body among the arena's walls and obstacles, in Bullet: the shapes,
// the broadphase, the contact solver, one substep of motion at an imposed velocity, the
// contact test, and place(), which returns the whole Bullet state to what a fresh world
// holds so that nothing leaks from one evaluation into the next. Internal to esc_sim: it
// includes Bullet, which only esc_sim's sources see (in the precision esc_sim links); World
// (world.hpp) keeps it behind its pimpl.
#include <BulletCollision/CollisionDispatch/btSphereBoxCollisionAlgorithm.h>
#include <btBulletDynamicsCommon.h>

#include <memory>
#include <vector>

#include "runtime/sim/arena.hpp"
#include "runtime/sim/drive.hpp"
#include "runtime/sim/geometry2d.hpp"
#include "runtime/sim/khepera_params.hpp"

namespace esc::sim {

class Body {
 public:
  // `geometry` is the arena's and must outlive the body. Bullet's arrays are grown here to
  // their working size, so nothing allocates afterwards; place() the body before moving it.
  Body(const ArenaSpec& arena, const KheperaParams& robot, double substep_s, const StaticGeometry2D& geometry);
  ~Body();
  // Bullet's objects point at each other.
  Body(const Body&) = delete;
  Body& operator=(const Body&) = delete;

  // The body at rest at `pose`, with no contact, broadphase pair or solver state left from
  // before: what a freshly built body at `pose` would be.
  void place(const Pose& pose);

  // One physics substep at the velocity `v` (drive.hpp); walls and obstacles stop the body.
  void move(const PlanarVelocity& v);

  // Whether the body touches a wall or an obstacle (its clearance is at most
  // kContactTolerance_m; the contact solver stops it at about 0).
  [[nodiscard]] bool touching() const noexcept;

  [[nodiscard]] Pose pose() const noexcept;
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
  void warm_up(const ArenaSpec& arena);
  void add_static_box(double cx, double cy, double hx, double hy, double angle_rad);
  void add_static(std::unique_ptr<btCollisionShape> shape, double x, double y, double angle_rad);
  [[nodiscard]] bool has_contact_points() const noexcept;

  double radius_m_;
  double substep_s_;
  const StaticGeometry2D& geometry_;

  // The dynamics world is declared last so it is destroyed first.
  std::unique_ptr<btDefaultCollisionConfiguration> config_;
  std::unique_ptr<btSphereBoxCollisionAlgorithm::CreateFunc> sphere_box_, box_sphere_;
  std::unique_ptr<btCollisionDispatcher> dispatcher_;
  std::unique_ptr<btAxisSweep3> broadphase_;
  std::unique_ptr<btSequentialImpulseConstraintSolver> solver_;
  std::vector<std::unique_ptr<btCollisionShape>> shapes_;
  std::vector<std::unique_ptr<btRigidBody>> statics_;
  std::unique_ptr<btSphereShape> body_shape_;
  std::unique_ptr<btRigidBody> body_;
  std::unique_ptr<btDiscreteDynamicsWorld> world_;
};

}  // namespace esc::sim
