#include "runtime/sim/world.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>

#include "runtime/sim/body.hpp"
#include "runtime/sim/bullet_world.hpp"
#include "runtime/sim/drive.hpp"
#include "runtime/sim/floor.hpp"
#include "runtime/sim/geometry2d.hpp"
#include "runtime/sim/goal_radar.hpp"
#include "runtime/sim/kinematic_body.hpp"
#include "runtime/sim/ir_sensor.hpp"
#include "runtime/sim/light_sensor.hpp"
#include "runtime/sim/neighbours.hpp"
#include "runtime/sim/motor.hpp"
#include "runtime/sim/outline.hpp"
#include "runtime/sim/rangefinder.hpp"
#include "runtime/sim/validate.hpp"

namespace esc::sim {

namespace {

// Free-pose rejection sampling gives up after this many draws.
constexpr int kFreePoseTries = 10000;

}  // namespace

// One robot of the world, its members declared in the order they are built: the models read
// the validated robot, the body reads the geometry and the Bullet world.
struct Robot {
  RobotParams robot;
  double substep_s;
  IrModel ir;
  LightModel light;
  RangefinderModel rangefinders;
  WheelMotor motor;
  DifferentialDrive drive;
  Floor floor;
  std::optional<Body> body;          // the differential drive's; the acceleration drive is kinematic
  KinematicBody kinematic;           // the acceleration drive's
  std::vector<Vec2> ground_points;   // the ground sensors' places in the body's frame
  GoalRadar radar;
  RobotState state;
  // A control step's working values (World::Impl::step_wheels).
  double target_l = 0.0, target_r = 0.0, vl = 0.0, vr = 0.0;
  Vec2 start, start_heading;
  Vec2 before;                       // where a Bullet substep found it
  bool collided = false;
  std::uint32_t bumped = 0;
  PlanarVelocity v;

  Robot(const ArenaSpec& a, const RobotParams& r, const StaticGeometry2D& geometry, BulletWorld* bullet)
      : robot(r),
        substep_s(r.control_step_s / r.physics_substeps),
        ir(r, geometry),
        light(r),
        rangefinders(r, geometry),
        motor(r.motor, substep_s),
        drive(r.wheel_base_m, substep_s),
        floor(a, r),
        kinematic(r),
        radar(r.radars) {
    if (bullet) body.emplace(a, r, substep_s, geometry, *bullet);
    for (const GroundMount& m : r.ground.mounts) ground_points.push_back(m.point());
  }

  [[nodiscard]] Pose pose() const noexcept { return body ? body->pose() : kinematic.pose(); }
  [[nodiscard]] Vec2 centre() const noexcept { return {state.pose.x_m, state.pose.y_m}; }
  // How far its sensors reach beyond its centre.
  [[nodiscard]] double sensing_reach_m() const noexcept {
    return std::max(ir.sensors() > 0 ? robot.body_radius_m + robot.ir.range_m : 0.0,
                    rangefinders.count() > 0 ? robot.rangefinders.range_m : 0.0);
  }
  // The bumpers whose sectors hold a contact at `at`.
  [[nodiscard]] std::uint32_t bumpers_toward(Vec2 at) const noexcept {
    const Pose from = pose();
    const double bearing = std::atan2(at.y - from.y_m, at.x - from.x_m) - from.heading_rad;
    std::uint32_t bits = 0;
    for (std::size_t i = 0; i < robot.bumpers.size(); ++i)
      if (robot.bumpers[i].holds(bearing)) bits |= 1U << i;
    return bits;
  }
  void finish_step(const Pose& pose, Vec2 start_at, Vec2 heading_at_start, bool hit) {
    state.pose = pose;
    const double dx_m = state.pose.x_m - start_at.x;
    const double dy_m = state.pose.y_m - start_at.y;
    state.displacement_m = std::hypot(dx_m, dy_m);
    state.forward_displacement_m =
        (dx_m * heading_at_start.x + dy_m * heading_at_start.y) / std::hypot(heading_at_start.x, heading_at_start.y);
    state.collided = hit;
    floor.observe({state.pose.x_m, state.pose.y_m}, state.floor);
  }
};

namespace {

void validate_group(const std::vector<RobotParams>& robots) {
  if (robots.empty()) throw std::invalid_argument("a world needs at least one robot");
  for (const RobotParams& r : robots) validate_robot(r);
  const RobotParams& first = robots.front();
  for (const RobotParams& r : robots) {
    if ((r.drive == DriveKind::Differential) != (first.drive == DriveKind::Differential))
      throw std::invalid_argument(
          "a group cannot mix the acceleration drive (kinematic, outside Bullet) with wheeled bodies");
    // One Bullet step moves every body: the robots share its substep.
    if (r.control_step_s != first.control_step_s || r.physics_substeps != first.physics_substeps)
      throw std::invalid_argument("the robots of a group must share their control step and physics substeps");
  }
}

}  // namespace

struct World::Impl {
  ArenaSpec arena;
  StaticGeometry2D geometry;
  std::unique_ptr<BulletWorld> bullet;        // the wheeled robots' world; none for the acceleration drive
  std::vector<std::unique_ptr<Robot>> robots;
  // A group's broadphase and scratch, sized once (empty for one robot).
  std::optional<Neighbours> grid;
  double largest_radius_m = 0.0;
  double largest_travel_m = 0.0;              // the farthest a robot moves in a control step
  std::vector<Vec2> centres;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;   // the step's pairs that may meet
  mutable std::vector<PlacedBody> seen;                          // the bodies one robot senses
  // Whether any robot gives off light, and the lights one robot reads then: the arena's and
  // the other robots' where they are.
  bool emitting = false;
  mutable std::vector<PlacedLight> lit;
  std::vector<Pose> starts;                                      // begin_epoch's poses
  Formation formation;                                           // where begin_epoch puts them

  Impl(const ArenaSpec& a, const std::vector<RobotParams>& r)
      : arena((validate_arena(a), validate_group(r), a)), geometry(a) {
    if (r.front().drive == DriveKind::Differential) bullet = std::make_unique<BulletWorld>(a, r.size());
    for (const RobotParams& p : r) robots.push_back(std::make_unique<Robot>(a, p, geometry, bullet.get()));
    if (robots.size() > 1) {
      double sensing = 0.0;
      for (const auto& robot : robots) {
        largest_radius_m = std::max(largest_radius_m, robot->robot.body_radius_m);
        largest_travel_m = std::max(largest_travel_m, robot->robot.motor.max_speed_mps * robot->robot.control_step_s);
        sensing = std::max(sensing, robot->sensing_reach_m());
      }
      grid.emplace(robots.size(), a.width_m, a.height_m, std::max(sensing + largest_radius_m, 4 * largest_radius_m));
      centres.resize(robots.size());
      pairs.reserve(robots.size() * (robots.size() - 1) / 2);
      seen.reserve(robots.size());
    }
    starts.reserve(robots.size());
    emitting = std::any_of(r.begin(), r.end(), [](const RobotParams& p) { return p.emission.intensity > 0.0; });
    if (emitting) lit.reserve(a.lights.size() + robots.size());
    for (std::size_t i = 0; i < robots.size(); ++i)
      if (robots[i]->body) robots[i]->body->set_index(i);
    if (robots.size() > 1 && bullet) warm_up_contacts();
    // Robot 0 where one robot starts; a group's others at random free places (an epoch places
    // them all again).
    starts.push_back(a.fixed_start.value_or(Pose{a.width_m / 2, a.height_m / 2, 0.0}));
    Rng rng(0);
    for (std::size_t i = 1; i < robots.size(); ++i) starts.push_back(random_free_pose(rng, kStartMargin_m, i, starts));
    reset(starts);
  }

  void reset(std::span<const Pose> poses) {
    if (poses.size() != robots.size())
      throw std::invalid_argument("a world of " + std::to_string(robots.size()) + " robots reset with " +
                                  std::to_string(poses.size()) + " poses");
    for (std::size_t i = 0; i < robots.size(); ++i)
      for (std::size_t j = i + 1; j < robots.size(); ++j) {
        const double apart = robots[i]->robot.body_radius_m + robots[j]->robot.body_radius_m;
        if (std::hypot(poses[i].x_m - poses[j].x_m, poses[i].y_m - poses[j].y_m) < apart)
          throw std::invalid_argument("robots " + std::to_string(i) + " and " + std::to_string(j) +
                                      " would start overlapping");
      }
    place(poses);
    if (bullet) bullet->reset_solver();
    for (const auto& robot : robots) {
      Robot& r = *robot;
      if (r.body) r.body->update_clearance();
      r.state = RobotState{};
      r.state.pose = r.pose();
      r.floor.reset({r.state.pose.x_m, r.state.pose.y_m}, r.state.floor);
    }
    index_robots();
  }

  // Every robot at rest at its pose: the bodies taken out of Bullet's world, the last first, then
  // put back, the first first (Body::take_out), so that its objects are in a fresh world's order.
  void place(std::span<const Pose> poses) {
    for (auto r = robots.rbegin(); r != robots.rend(); ++r)
      if ((*r)->body) (*r)->body->take_out();
    for (std::size_t i = 0; i < robots.size(); ++i) {
      Robot& r = *robots[i];
      if (r.body) r.body->put_back(poses[i]);
      else r.kinematic.place(poses[i]);
    }
  }

  // The grid over the robots where they are now: the next step's pairs, and what they sense.
  void index_robots() noexcept {
    if (!grid) return;
    for (std::size_t i = 0; i < robots.size(); ++i) centres[i] = robots[i]->centre();
    grid->build(centres);
  }

  void check_commands(std::size_t n) const {
    if (n != robots.size())
      throw std::invalid_argument("a world of " + std::to_string(robots.size()) + " robots stepped with " +
                                  std::to_string(n) + " commands");
  }

  void step(std::span<const DriveCommand> commands, Rng* rng) {
    if (bullet) step_wheels(commands, rng);
    else step_kinematic(commands);
    index_robots();
  }

  // Motors, drives and bodies substep by substep; the floor counts energy at every substep
  // and observes the rest at the end of the step. One Bullet step moves every body: it is
  // taken when any body is near a wall, an obstacle or another body, or a contact point is
  // cached; otherwise each body is integrated alone.
  void step_wheels(std::span<const DriveCommand> commands, Rng* rng) {
    for (std::size_t i = 0; i < robots.size(); ++i) {
      Robot& r = *robots[i];
      r.target_l = r.motor.noisy(r.motor.target(commands[i].left), rng);
      r.target_r = r.motor.noisy(r.motor.target(commands[i].right), rng);
      r.start = r.body->position();
      r.start_heading = r.body->heading();
      r.vl = r.state.wheel_speed_mps[0];
      r.vr = r.state.wheel_speed_mps[1];
      r.collided = false;
      r.bumped = 0;
    }
    find_pairs();
    const int substeps = robots.front()->robot.physics_substeps;
    for (int k = 0; k < substeps; ++k) {
      bool near = false;
      for (const auto& robot : robots) {
        Robot& r = *robot;
        r.vl = r.motor.step(r.vl, r.target_l);
        r.vr = r.motor.step(r.vr, r.target_r);
        r.v = r.drive.velocity(r.vl, r.vr, r.body->heading());
        near = r.body->set_velocity(r.v) || near;
      }
      near = near || pairs_near();
      const bool stepped = bullet->has_contact_points() || near;
      if (stepped) {
        for (const auto& robot : robots) {
          robot->body->prepare_bullet_step();
          robot->before = robot->body->position();
        }
        bullet->step(robots.front()->substep_s);
        if (grid && pushed()) {   // beyond what the pairs were found for: find them again
          index_robots();
          find_pairs();
        }
      } else {
        for (const auto& robot : robots) robot->body->integrate(robot->v);
      }
      for (const auto& robot : robots) {
        Robot& r = *robot;
        r.body->update_clearance();
        if (r.body->touching()) {
          r.collided = true;
          if (!r.robot.bumpers.empty()) r.bumped |= r.bumpers_toward(r.body->contact_point());
        }
      }
      if (stepped) touch_pairs();
      for (const auto& robot : robots) robot->floor.substep(robot->body->position());
    }
    for (const auto& robot : robots) {
      Robot& r = *robot;
      r.state.wheel_speed_mps[0] = r.vl;
      r.state.wheel_speed_mps[1] = r.vr;
      r.finish_step(r.body->pose(), r.start, r.start_heading, r.collided);
      r.state.bumped = r.bumped;
    }
  }

  // The pairs of robots that may come near each other in this control step: their discs
  // apart by at most both top speeds over the step (and the margins) at its start.
  void find_pairs() {
    pairs.clear();
    if (!grid) return;
    for (std::size_t i = 0; i < robots.size(); ++i) {
      const Robot& a = *robots[i];
      const double a_travel = a.robot.motor.max_speed_mps * a.robot.control_step_s;
      grid->near(centres[i], 2 * largest_radius_m + 2 * largest_travel_m + 2 * kFreeSpaceMargin_m, [&](std::size_t j) {
        if (j <= i) return;
        const Robot& b = *robots[j];
        const double reach = a.robot.body_radius_m + b.robot.body_radius_m + a_travel +
                             b.robot.motor.max_speed_mps * b.robot.control_step_s + 2 * kFreeSpaceMargin_m;
        const double ex = centres[j].x - centres[i].x, ey = centres[j].y - centres[i].y;
        if (ex * ex + ey * ey <= reach * reach)
          pairs.emplace_back(static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j));
      });
    }
  }

  // Whether a pair's discs may meet within this substep.
  [[nodiscard]] bool pairs_near() const noexcept {
    for (const auto& [i, j] : pairs) {
      const Robot& a = *robots[i];
      const Robot& b = *robots[j];
      const Vec2 pa = a.body->position(), pb = b.body->position();
      const double keep = a.robot.body_radius_m + b.robot.body_radius_m + a.v.travel_m + b.v.travel_m + kFreeSpaceMargin_m;
      const double ex = pb.x - pa.x, ey = pb.y - pa.y;
      if (ex * ex + ey * ey <= keep * keep) return true;
    }
    return false;
  }

  // Whether the last Bullet step moved a robot farther than its own top speed would (another
  // robot pushed it).
  [[nodiscard]] bool pushed() const noexcept {
    for (const auto& robot : robots) {
      const Robot& r = *robot;
      const Vec2 p = r.body->position();
      const double reach = r.robot.motor.max_speed_mps * r.substep_s + kFreeSpaceMargin_m;
      if ((p.x - r.before.x) * (p.x - r.before.x) + (p.y - r.before.y) * (p.y - r.before.y) > reach * reach) return true;
    }
    return false;
  }

  // Robots touching each other after a Bullet step, found in Bullet's own contacts (whatever
  // pushed them there): both collided, each one's bumpers toward the contact.
  void touch_pairs() {
    bullet->for_each_body_contact(kContactTolerance_m, [&](std::size_t i, std::size_t j, Vec2 at) {
      for (Robot* r : {robots[i].get(), robots[j].get()}) {
        r->collided = true;
        if (!r->robot.bumpers.empty()) r->bumped |= r->bumpers_toward(at);
      }
    });
  }

  // Grows Bullet's arrays (pair cache, manifolds, islands, solver pools) to a crowd's, so that
  // a crowd's step never allocates: the bodies packed in a square lattice about the arena's
  // centre, each overlapping its four nearest and within Bullet's contact threshold of the next
  // four, step a few times, then reset() places them. (Piled all on one spot, N robots would
  // grow N^2 / 2 manifolds, 70 MB for 256; a crowd holds a few per robot.)
  void warm_up_contacts() {
    const Vec2 centre{arena.width_m / 2, arena.height_m / 2};
    const auto side = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(robots.size()))));
    const double spacing = 1.6 * largest_radius_m;
    std::vector<Pose> pile;
    for (std::size_t i = 0; i < robots.size(); ++i) {
      const double col = static_cast<double>(i % side) - 0.5 * static_cast<double>(side - 1);
      const double row = static_cast<double>(i / side) - 0.5 * static_cast<double>(side - 1);
      pile.push_back({centre.x + spacing * col, centre.y + spacing * row, static_cast<double>(i)});
    }
    place(pile);
    constexpr int kWarmUpSteps = 8;
    for (int k = 0; k < kWarmUpSteps; ++k) {
      for (const auto& robot : robots) {
        const Vec2 heading = robot->body->heading();
        (void)robot->body->set_velocity({0.01 * heading.x, 0.01 * heading.y, 1.0, 0.0005});
        robot->body->prepare_bullet_step();
      }
      bullet->step(robots.front()->substep_s);
    }
  }

  // One move of each navigator, in robot order (a move is cancelled by a robot that has
  // already moved where it now stands); the floor counts energy as many times as a wheeled
  // robot's substeps would, at the position the step ends at.
  void step_kinematic(std::span<const DriveCommand> commands) {
    for (std::size_t i = 0; i < robots.size(); ++i) {
      Robot& r = *robots[i];
      const Pose start = r.kinematic.pose();
      const Vec2 start_facing = r.kinematic.facing();
      const std::span<const PlacedBody> others = bodies_near(i);
      const bool collided = !r.kinematic.move(commands[i].left, commands[i].right, geometry, others);
      r.state.wheel_speed_mps[0] = r.kinematic.turn_radps();
      r.state.wheel_speed_mps[1] = r.kinematic.speed_mps();
      for (int k = 0; k < r.robot.physics_substeps; ++k) r.floor.substep({r.kinematic.pose().x_m, r.kinematic.pose().y_m});
      r.finish_step(r.kinematic.pose(), {start.x_m, start.y_m}, start_facing, collided);
      if (i + 1 < robots.size()) centres[i] = r.centre();   // the robots after it see where it went
      // A cancelled move: towards the wall nearest to where it would have gone, or the robot
      // that stopped it, from where it stayed.
      r.state.bumped = collided && !r.robot.bumpers.empty() ? r.bumpers_toward(blocker(r, others)) : 0;
    }
  }

  // What cancelled a navigator's move: the nearest point of the walls, unless its attempted
  // centre clears them and another robot's disc held it back.
  [[nodiscard]] Vec2 blocker(const Robot& r, std::span<const PlacedBody> others) const noexcept {
    const Vec2 to = r.kinematic.attempted();
    if (others.empty() || geometry.clearance(to, r.robot.body_radius_m) < r.robot.body_radius_m)
      return geometry.nearest_point(to);
    const PlacedBody* nearest = &others.front();
    double best = StaticGeometry2D::kNoHit;
    for (const PlacedBody& b : others) {
      const double d = std::hypot(to.x - b.centre.x, to.y - b.centre.y) - b.radius_m;
      if (d < best) best = d, nearest = &b;
    }
    return nearest->centre;
  }

  // The bodies of the robots other than `i` that its sensors or its step may reach, placed
  // where they are now (none for a robot alone).
  std::span<const PlacedBody> bodies_near(std::size_t i) const {
    seen.clear();
    if (!grid) return {};
    const Robot& a = *robots[i];
    // The grid's centres may be a step old (navigators moved before this one): their travel too.
    const double reach = a.sensing_reach_m() + a.robot.body_radius_m + 2 * largest_travel_m;
    const Vec2 c = a.centre();
    grid->near(c, reach + largest_radius_m, [&](std::size_t j) {
      if (j == i) return;
      Robot& b = *robots[j];
      const Vec2 at = centres[j];
      const double keep = reach + b.robot.body_radius_m;   // exact: centres[j] is where it is
      if ((at.x - c.x) * (at.x - c.x) + (at.y - c.y) * (at.y - c.y) > keep * keep) return;
      seen.push_back({at, b.robot.body_radius_m, b.body ? b.body->placed_outline() : std::span<const Vec2>{}});
    });
    return seen;
  }

  [[nodiscard]] std::vector<Pose> random_free_poses(Rng& rng, double margin_m, std::size_t count) const {
    std::vector<Pose> poses;
    for (std::size_t i = 0; i < count; ++i) poses.push_back(random_free_pose(rng, margin_m, i, poses));
    return poses;
  }

  // A line's or a circle's poses: a heading, then a centre where the formation's whole reach
  // stays in the arena, drawn until every body clears the walls and obstacles.
  void formation_poses(Rng& rng, std::vector<Pose>& poses) const {
    const std::size_t n = robots.size();
    double radius = 0.0;
    for (const auto& r : robots) radius = std::max(radius, r->robot.body_radius_m);
    const double keep = radius + kStartMargin_m;
    const double reach = formation_reach(formation, n) + keep;
    for (int t = 0; t < kFreePoseTries; ++t) {
      const double heading = rng.uniform(-std::numbers::pi, std::numbers::pi);
      const Vec2 centre{rng.uniform(reach, arena.width_m - reach), rng.uniform(reach, arena.height_m - reach)};
      poses.clear();
      bool clear = true;
      for (std::size_t i = 0; i < n && clear; ++i) {
        poses.push_back(formation_pose(formation, n, i, centre, heading));
        clear = geometry.clearance({poses.back().x_m, poses.back().y_m}, keep) >= keep;
      }
      if (clear) return;
    }
    throw std::runtime_error("the arena has no free space for the group's formation (no place found that keeps "
                             "every body " + std::to_string(kStartMargin_m) + " m clear of every wall and obstacle)");
  }

  [[nodiscard]] Pose random_free_pose(Rng& rng, double margin_m, std::size_t i, std::span<const Pose> before) const {
    const double radius = robots[i]->robot.body_radius_m;
    const double keep = radius + margin_m;
    const auto clear_of_robots = [&](double x, double y) {
      for (std::size_t k = 0; k < before.size(); ++k) {
        const double apart = keep + robots[k]->robot.body_radius_m;
        if ((x - before[k].x_m) * (x - before[k].x_m) + (y - before[k].y_m) * (y - before[k].y_m) < apart * apart)
          return false;
      }
      return true;
    };
    if (2 * keep < arena.width_m && 2 * keep < arena.height_m) {
      for (int t = 0; t < kFreePoseTries; ++t) {
        const double x = rng.uniform(keep, arena.width_m - keep);
        const double y = rng.uniform(keep, arena.height_m - keep);
        if (geometry.clearance({x, y}, keep) >= keep && clear_of_robots(x, y))
          return {x, y, rng.uniform(-std::numbers::pi, std::numbers::pi)};
      }
    }
    throw std::runtime_error(
        (i == 0 ? std::string("the arena has no free space for the robot")
                : "the arena has no free space for robot " + std::to_string(i) + " beside the robots before it") +
        " (no pose found that keeps the body " + std::to_string(margin_m) + " m clear of every wall and obstacle)");
  }
};

World::World(const ArenaSpec& arena, const RobotParams& robot)
    : impl_(std::make_unique<Impl>(arena, std::vector<RobotParams>{robot})) {}
World::World(const ArenaSpec& arena, const std::vector<RobotParams>& robots)
    : impl_(std::make_unique<Impl>(arena, robots)) {}
World::~World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

Pose World::random_free_pose(Rng& rng, double margin_m) const { return impl_->random_free_pose(rng, margin_m, 0, {}); }
std::vector<Pose> World::random_free_poses(Rng& rng, double margin_m) const {
  return impl_->random_free_poses(rng, margin_m, impl_->robots.size());
}
std::size_t World::robots() const noexcept { return impl_->robots.size(); }
void World::place_zones(Rng& rng) {
  Floor& first = impl_->robots.front()->floor;
  first.place_zones(rng, impl_->geometry);
  for (std::size_t i = 1; i < impl_->robots.size(); ++i) impl_->robots[i]->floor.take_zones(first);
}
void World::reset(const Pose& pose) { impl_->reset({&pose, 1}); }
void World::reset(std::span<const Pose> poses) { impl_->reset(poses); }
Pose World::begin_epoch(Rng& rng) {
  place_zones(rng);
  std::vector<Pose>& poses = impl_->starts;
  poses.clear();
  const FormationKind kind = impl_->formation.kind;
  if (kind == FormationKind::At) {
    poses = impl_->formation.at;
  } else if (kind == FormationKind::Random || impl_->robots.size() == 1) {
    // A line or a circle of one robot is no formation: it starts where a robot alone does.
    for (std::size_t i = 0; i < impl_->robots.size(); ++i)
      poses.push_back(i == 0 && impl_->arena.fixed_start ? *impl_->arena.fixed_start
                                                         : impl_->random_free_pose(rng, kStartMargin_m, i, poses));
  } else {
    impl_->formation_poses(rng, poses);
  }
  impl_->reset(poses);
  return poses.front();
}

void World::set_formation(const Formation& formation) {
  std::vector<double> radii;
  for (const auto& r : impl_->robots) radii.push_back(r->robot.body_radius_m);
  if (const std::string why = formation_problem(formation, impl_->arena, radii, kStartMargin_m); !why.empty())
    throw std::invalid_argument("the group's formation: " + why);
  impl_->formation = formation;
}
void World::step(double left_command, double right_command, Rng& rng) {
  const DriveCommand command{left_command, right_command};
  step({&command, 1}, rng);
}
void World::step(double left_command, double right_command) {
  const DriveCommand command{left_command, right_command};
  impl_->check_commands(1);
  const Robot& r = *impl_->robots.front();
  if (r.body && r.motor.has_noise()) throw std::logic_error("World::step: a robot with motor noise needs its noise stream");
  impl_->step({&command, 1}, nullptr);
}
void World::step(std::span<const DriveCommand> commands, Rng& rng) {
  impl_->check_commands(commands.size());
  impl_->step(commands, &rng);
}
void World::read_ir(std::array<double, kIrSensors>& out, Rng& rng, std::size_t robot) const {
  const Robot& r = *impl_->robots[robot];
  r.ir.read(r.state.pose, out, rng, r.ir.sensors() > 0 ? impl_->bodies_near(robot) : std::span<const PlacedBody>{});
}
void World::read_light(std::array<double, kLightSensors>& out, Rng& rng, std::size_t robot) const {
  const Robot& r = *impl_->robots[robot];
  std::span<const PlacedLight> lights = r.floor.lights();
  if (impl_->emitting) {
    std::vector<PlacedLight>& lit = impl_->lit;
    lit.assign(lights.begin(), lights.end());
    for (std::size_t j = 0; j < impl_->robots.size(); ++j) {
      const Robot& other = *impl_->robots[j];
      if (j == robot || !(other.robot.emission.intensity > 0.0)) continue;
      lit.push_back({other.state.pose.x_m, other.state.pose.y_m, other.robot.emission.height_m,
                     other.robot.emission.intensity});
    }
    lights = lit;
  }
  r.light.read(r.state.pose, impl_->geometry, lights.data(), lights.size(), out, rng);
}
void World::read_rangefinders(std::span<double> out, std::size_t robot) const {
  const Robot& r = *impl_->robots[robot];
  if (r.rangefinders.count() == 0) return;
  const std::span<const PlacedBody> others = impl_->bodies_near(robot);
  if (r.body) r.rangefinders.read(r.state.pose, out, others);
  else r.rangefinders.read(r.state.pose, r.kinematic.facing(), out, others);
}
void World::read_ground(std::span<double> out, std::size_t robot) const {
  const Robot& r = *impl_->robots[robot];
  const std::vector<Vec2>& points = r.ground_points;
  if (points.empty()) return;  // no sine and cosine for a robot without ground sensors
  std::array<Vec2, kMaxGroundSensors> at;
  place_points(points, r.state.pose, at);
  for (std::size_t i = 0; i < points.size() && i < out.size(); ++i) out[i] = r.floor.visible_at(at[i]) ? 1.0 : 0.0;
}

int World::goal_slice(std::size_t robot) const noexcept {
  const Robot& r = *impl_->robots[robot];
  const std::optional<Vec2>& goal = impl_->arena.goal;
  if (!goal || r.robot.radars == 0) return -1;
  const Pose& pose = r.state.pose;
  const Vec2 facing = r.body ? Vec2{std::cos(pose.heading_rad), std::sin(pose.heading_rad)} : r.kinematic.facing();
  return r.radar.slice(pose, facing, *goal);
}

// The zones and lights are where robot 0's floor placed them, and every floor took them.
std::span<const Vec2> World::zone_centers() const noexcept { return impl_->robots.front()->floor.zone_centers(); }
std::span<const Vec2> World::light_positions() const noexcept { return impl_->robots.front()->floor.light_positions(); }
bool World::in_zone(std::size_t zone, Vec2 p) const noexcept { return impl_->robots.front()->floor.in_zone(zone, p); }
int World::sweep_columns() const noexcept { return impl_->robots.front()->floor.sweep_columns(); }
int World::sweep_rows() const noexcept { return impl_->robots.front()->floor.sweep_rows(); }
const RobotState& World::state(std::size_t robot) const noexcept { return impl_->robots[robot]->state; }
const RobotParams& World::robot(std::size_t robot) const noexcept { return impl_->robots[robot]->robot; }
const ArenaSpec& World::arena() const noexcept { return impl_->arena; }

}  // namespace esc::sim
