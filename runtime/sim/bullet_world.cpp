#include "runtime/sim/bullet_world.hpp"

#include <mutex>

namespace esc::sim {

namespace {

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

}  // namespace

BulletWorld::BulletWorld(const ArenaSpec& a, std::size_t bodies) {
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
  // Two robots' spheres: Bullet's sphere-sphere algorithm reports a contact only once they
  // overlap, so robots closing at full speed would sink a substep's travel into each other
  // (6 mm for two Kheperas) before the solver pushed them apart. GJK's convex-convex algorithm
  // reports the gap while it is within the contact breaking threshold, as the sphere-box one
  // does, so the solver stops them at contact. (No sphere-sphere pair exists with one robot.)
  dispatcher_->registerCollisionCreateFunc(
      SPHERE_SHAPE_PROXYTYPE, SPHERE_SHAPE_PROXYTYPE,
      config_->getCollisionAlgorithmCreateFunc(CONVEX_HULL_SHAPE_PROXYTYPE, CONVEX_HULL_SHAPE_PROXYTYPE));
  // Manifolds keep points up to gContactBreakingThreshold (0.02 m) apart, not a
  // fraction of the body size, so the solver sees a wall before the body reaches it.
  dispatcher_->setDispatcherFlags(dispatcher_->getDispatcherFlags() &
                                  ~btCollisionDispatcher::CD_USE_RELATIVE_CONTACT_BREAKING_THRESHOLD);
  const double pad = kWallThickness_m + 1.0;
  const auto handles =
      static_cast<unsigned short>(a.boxes.size() + a.walls.size() + a.cylinders.size() + 7 + bodies);
  // Sweep and prune: its state after removing and re-adding the bodies depends only on
  // where the objects are, which Body::place relies on. No ray accelerator (no Bullet rays).
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
}

BulletWorld::~BulletWorld() = default;

void BulletWorld::add_static_box(double cx, double cy, double hx, double hy, double angle_rad) {
  auto shape = std::make_unique<btBoxShape>(btVector3(bt(hx), bt(hy), bt(kStaticHeight_m / 2)));
  shape->setMargin(kCollisionMargin_m);
  add_static(std::move(shape), cx, cy, angle_rad);
}

void BulletWorld::add_static(std::unique_ptr<btCollisionShape> shape, double x, double y, double angle_rad) {
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

}  // namespace esc::sim
