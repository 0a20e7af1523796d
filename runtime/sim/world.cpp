#include "runtime/sim/world.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>

#include "runtime/sim/body.hpp"
#include "runtime/sim/drive.hpp"
#include "runtime/sim/floor.hpp"
#include "runtime/sim/geometry2d.hpp"
#include "runtime/sim/goal_radar.hpp"
#include "runtime/sim/kinematic_body.hpp"
#include "runtime/sim/ir_sensor.hpp"
#include "runtime/sim/light_sensor.hpp"
#include "runtime/sim/motor.hpp"
#include "runtime/sim/outline.hpp"
#include "runtime/sim/rangefinder.hpp"
#include "runtime/sim/validate.hpp"

namespace esc::sim {

namespace {

// Free-pose rejection sampling gives up after this many draws.
constexpr int kFreePoseTries = 10000;

}  // namespace

// Declared in the order they are built: the models read the validated arena and robot, the
// body reads the geometry.
struct World::Impl {
  ArenaSpec arena;
  RobotParams robot;
  double substep_s;
  StaticGeometry2D geometry;
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

  Impl(const ArenaSpec& a, const RobotParams& r)
      : arena((validate_arena(a), a)),
        robot((validate_robot(r), r)),
        substep_s(r.control_step_s / r.physics_substeps),
        geometry(a),
        ir(r, geometry),
        light(r),
        rangefinders(r, geometry),
        motor(r.motor, substep_s),
        drive(r.wheel_base_m, substep_s),
        floor(a, r),
        kinematic(r),
        radar(r.radars) {
    if (r.drive == DriveKind::Differential) body.emplace(a, r, substep_s, geometry);
    for (const GroundMount& m : r.ground.mounts) ground_points.push_back(m.point());
    reset(a.fixed_start.value_or(Pose{a.width_m / 2, a.height_m / 2, 0.0}));
  }

  void reset(const Pose& pose) {
    if (body) body->place(pose);
    else kinematic.place(pose);
    state = RobotState{};
    state.pose = body ? body->pose() : kinematic.pose();
    floor.reset({state.pose.x_m, state.pose.y_m}, state.floor);
  }

  void step(double left_command, double right_command, Rng* rng) {
    if (body) step_wheels(left_command, right_command, rng);
    else step_kinematic(left_command, right_command);
  }

  // Motors, drive and body substep by substep; the floor counts energy at every substep
  // and observes the rest at the end of the step.
  void step_wheels(double left_command, double right_command, Rng* rng) {
    const double target_l = motor.noisy(motor.target(left_command), rng);
    const double target_r = motor.noisy(motor.target(right_command), rng);
    const Vec2 start = body->position();
    const Vec2 start_heading = body->heading();
    double vl = state.wheel_speed_mps[0];
    double vr = state.wheel_speed_mps[1];
    bool collided = false;
    std::uint32_t bumped = 0;
    for (int i = 0; i < robot.physics_substeps; ++i) {
      vl = motor.step(vl, target_l);
      vr = motor.step(vr, target_r);
      body->move(drive.velocity(vl, vr, body->heading()));
      if (body->touching()) {
        collided = true;
        if (!robot.bumpers.empty()) bumped |= bumpers_toward(body->pose(), body->contact_point());
      }
      floor.substep(body->position());
    }
    state.wheel_speed_mps[0] = vl;
    state.wheel_speed_mps[1] = vr;
    finish_step(body->pose(), start, start_heading, collided);
    state.bumped = bumped;
  }

  // One move of the navigator; the floor counts energy as many times as a wheeled robot's
  // substeps would, at the position the step ends at.
  void step_kinematic(double turn_command, double speed_command) {
    const Pose start = kinematic.pose();
    const Vec2 start_facing = kinematic.facing();
    const bool collided = !kinematic.move(turn_command, speed_command, geometry);
    state.wheel_speed_mps[0] = kinematic.turn_radps();
    state.wheel_speed_mps[1] = kinematic.speed_mps();
    for (int i = 0; i < robot.physics_substeps; ++i) floor.substep({kinematic.pose().x_m, kinematic.pose().y_m});
    finish_step(kinematic.pose(), {start.x_m, start.y_m}, start_facing, collided);
    // A cancelled move: towards the wall nearest to where it would have gone, from where it stayed.
    state.bumped = collided && !robot.bumpers.empty()
                       ? bumpers_toward(state.pose, geometry.nearest_point(kinematic.attempted()))
                       : 0;
  }

  // The bumpers whose sectors hold a contact at `at`, seen from a body at `from`.
  [[nodiscard]] std::uint32_t bumpers_toward(const Pose& from, Vec2 at) const noexcept {
    const double bearing = std::atan2(at.y - from.y_m, at.x - from.x_m) - from.heading_rad;
    std::uint32_t bits = 0;
    for (std::size_t i = 0; i < robot.bumpers.size(); ++i)
      if (robot.bumpers[i].holds(bearing)) bits |= 1U << i;
    return bits;
  }

  void finish_step(const Pose& pose, Vec2 start, Vec2 start_heading, bool collided) {
    state.pose = pose;
    const double dx_m = state.pose.x_m - start.x;
    const double dy_m = state.pose.y_m - start.y;
    state.displacement_m = std::hypot(dx_m, dy_m);
    state.forward_displacement_m =
        (dx_m * start_heading.x + dy_m * start_heading.y) / std::hypot(start_heading.x, start_heading.y);
    state.collided = collided;
    floor.observe({state.pose.x_m, state.pose.y_m}, state.floor);
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

World::World(const ArenaSpec& arena, const RobotParams& robot)
    : impl_(std::make_unique<Impl>(arena, robot)) {}
World::~World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

Pose World::random_free_pose(Rng& rng, double margin_m) const {
  return impl_->random_free_pose(rng, margin_m);
}
void World::place_zones(Rng& rng) { impl_->floor.place_zones(rng, impl_->geometry); }
void World::reset(const Pose& pose) { impl_->reset(pose); }
Pose World::begin_epoch(Rng& rng) {
  place_zones(rng);
  const Pose pose = impl_->arena.fixed_start ? *impl_->arena.fixed_start : random_free_pose(rng);
  impl_->reset(pose);
  return pose;
}
void World::step(double left_command, double right_command, Rng& rng) {
  impl_->step(left_command, right_command, &rng);
}
void World::step(double left_command, double right_command) {
  if (impl_->body && impl_->motor.has_noise()) throw std::logic_error("World::step: a robot with motor noise needs its noise stream");
  impl_->step(left_command, right_command, nullptr);
}
void World::read_ir(std::array<double, kIrSensors>& out, Rng& rng) const {
  impl_->ir.read(impl_->state.pose, out, rng);
}
void World::read_light(std::array<double, kLightSensors>& out, Rng& rng) const {
  const std::span<const PlacedLight> lights = impl_->floor.lights();
  impl_->light.read(impl_->state.pose, impl_->geometry, lights.data(), lights.size(), out, rng);
}
void World::read_rangefinders(std::span<double> out) const {
  if (impl_->body) impl_->rangefinders.read(impl_->state.pose, out);
  else impl_->rangefinders.read(impl_->state.pose, impl_->kinematic.facing(), out);
}
void World::read_ground(std::span<double> out) const {
  const std::vector<Vec2>& points = impl_->ground_points;
  if (points.empty()) return;  // no sine and cosine for a robot without ground sensors
  std::array<Vec2, kMaxGroundSensors> at;
  place_points(points, impl_->state.pose, at);
  for (std::size_t i = 0; i < points.size() && i < out.size(); ++i) out[i] = impl_->floor.visible_at(at[i]) ? 1.0 : 0.0;
}

int World::goal_slice() const noexcept {
  const std::optional<Vec2>& goal = impl_->arena.goal;
  if (!goal || impl_->robot.radars == 0) return -1;
  const Pose& pose = impl_->state.pose;
  const Vec2 facing = impl_->body ? Vec2{std::cos(pose.heading_rad), std::sin(pose.heading_rad)} : impl_->kinematic.facing();
  return impl_->radar.slice(pose, facing, *goal);
}

std::span<const Vec2> World::zone_centers() const noexcept { return impl_->floor.zone_centers(); }
std::span<const Vec2> World::light_positions() const noexcept { return impl_->floor.light_positions(); }
bool World::in_zone(std::size_t zone, Vec2 p) const noexcept { return impl_->floor.in_zone(zone, p); }
int World::sweep_columns() const noexcept { return impl_->floor.sweep_columns(); }
int World::sweep_rows() const noexcept { return impl_->floor.sweep_rows(); }
const RobotState& World::state() const noexcept { return impl_->state; }
const RobotParams& World::robot() const noexcept { return impl_->robot; }
const ArenaSpec& World::arena() const noexcept { return impl_->arena; }

}  // namespace esc::sim
