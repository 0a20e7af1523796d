#pragma once
// The arena in Bullet: its walls and obstacles as static shapes, the broadphase, the contact
// solver and the dynamics world that every dynamic robot body of a World (body.hpp) moves
// in, so that bodies collide with each other through Bullet as they do with the walls.
// Internal to esc_sim, as body.hpp: it includes Bullet.
#include <BulletCollision/CollisionDispatch/btSphereBoxCollisionAlgorithm.h>
#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <cstddef>
#include <memory>
#include <vector>

#include "runtime/sim/arena.hpp"

namespace esc::sim {

class BulletWorld {
 public:
  // Room in the broadphase for `bodies` robot bodies.
  BulletWorld(const ArenaSpec& arena, std::size_t bodies);
  ~BulletWorld();
  BulletWorld(const BulletWorld&) = delete;
  BulletWorld& operator=(const BulletWorld&) = delete;

  [[nodiscard]] btDiscreteDynamicsWorld& world() noexcept { return *world_; }
  // One substep of every body, at the velocities set on them.
  void step(double substep_s) { world_->stepSimulation(static_cast<btScalar>(substep_s), 0, static_cast<btScalar>(substep_s)); }
  // The solver's warm-start state and random seed as a fresh world's (after placing bodies).
  void reset_solver() {
    solver_->reset();
    solver_->setRandSeed(0);
  }
  // Whether any contact point is cached between any two objects (up to 2 cm apart).
  [[nodiscard]] bool has_contact_points() const noexcept {
    const int n = dispatcher_->getNumManifolds();
    for (int i = 0; i < n; ++i)
      if (dispatcher_->getManifoldByIndexInternal(i)->getNumContacts() > 0) return true;
    return false;
  }
  // Calls f(i, j, at) for every pair of robot bodies (user indices i < j, set by Body) whose
  // cached contact points come within `within_m` (Bullet's distance: negative in penetration),
  // `at` midway between the two surfaces at the nearest point.
  template <class F>
  void for_each_body_contact(double within_m, F&& f) const {
    const int n = dispatcher_->getNumManifolds();
    for (int m = 0; m < n; ++m) {
      const btPersistentManifold* manifold = dispatcher_->getManifoldByIndexInternal(m);
      const int a = manifold->getBody0()->getUserIndex();
      const int b = manifold->getBody1()->getUserIndex();
      if (a < 0 || b < 0) continue;
      const btManifoldPoint* nearest = nullptr;
      for (int k = 0; k < manifold->getNumContacts(); ++k) {
        const btManifoldPoint& p = manifold->getContactPoint(k);
        if (p.getDistance() <= within_m && (nearest == nullptr || p.getDistance() < nearest->getDistance())) nearest = &p;
      }
      if (nearest == nullptr) continue;
      const btVector3& pa = nearest->getPositionWorldOnA();
      const btVector3& pb = nearest->getPositionWorldOnB();
      f(static_cast<std::size_t>(std::min(a, b)), static_cast<std::size_t>(std::max(a, b)),
        Vec2{(pa.x() + pb.x()) / 2, (pa.y() + pb.y()) / 2});
    }
  }

 private:
  void add_static_box(double cx, double cy, double hx, double hy, double angle_rad);
  void add_static(std::unique_ptr<btCollisionShape> shape, double x, double y, double angle_rad);

  // The dynamics world is declared last so it is destroyed first.
  std::unique_ptr<btDefaultCollisionConfiguration> config_;
  std::unique_ptr<btSphereBoxCollisionAlgorithm::CreateFunc> sphere_box_, box_sphere_;
  std::unique_ptr<btCollisionDispatcher> dispatcher_;
  std::unique_ptr<btAxisSweep3> broadphase_;
  std::unique_ptr<btSequentialImpulseConstraintSolver> solver_;
  std::vector<std::unique_ptr<btCollisionShape>> shapes_;
  std::vector<std::unique_ptr<btRigidBody>> statics_;
  std::unique_ptr<btDiscreteDynamicsWorld> world_;
};

// Shape constants the arena's statics and the bodies share.
// Collision margin of every Bullet shape (inside the shape's outer surface, so the
// surfaces are exact); small against the 27.5 mm body, large enough for robust GJK.
inline constexpr btScalar kCollisionMargin_m = 0.0005F;
// Walls are boxes this thick outside the inner rectangle; static shapes are this tall
// (centred on the plane) so every contact normal is horizontal.
inline constexpr double kWallThickness_m = 0.1;
inline constexpr double kStaticHeight_m = 0.4;
// Coulomb friction between bodies and walls (Bullet's default), no restitution.
inline constexpr btScalar kContactFriction = 0.5F;
inline constexpr btScalar kRestitution = 0.0F;

[[nodiscard]] inline btScalar bt(double v) noexcept { return static_cast<btScalar>(v); }

}  // namespace esc::sim
