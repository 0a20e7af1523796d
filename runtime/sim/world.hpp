#pragma once
// The simulated robots in their arena, as the evaluation loop sees them: the façade over the
// bodies in one Bullet world (body.hpp, bullet_world.hpp), the floor (floor.hpp: zones, lights,
// energy, sweep grid), the motors and the drive (motor.hpp, drive.hpp) and the sensors. One
// robot, or a group (docs/groups.md): the robots collide through Bullet, and their IR sensors
// and rangefinders meet each other's bodies, found through a grid (neighbours.hpp) rather than
// by testing every pair. Calls without a robot index are robot 0's. A worker builds a World once
// and reuses it for every evaluation: reset() returns it to a state indistinguishable from a
// freshly built world (body state, contact manifolds, broadphase pairs, solver seed), so a
// trajectory depends only on its start pose, its commands and its noise stream, never on
// what the world simulated before.
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "runtime/core/rng.hpp"
#include "runtime/sim/arena.hpp"
#include "runtime/sim/floor.hpp"
#include "runtime/sim/formation.hpp"
#include "runtime/sim/robot_params.hpp"
#include "runtime/sim/light_sensor.hpp"

namespace esc::sim {

inline constexpr int kIrSensors = kMaxIrSensors;   // `ir` slots; a robot fills its sensors' count of them

// Physical state after the last control step; what observables are computed from.
struct RobotState {
  Pose pose;
  // The drive's two actuators after the step: the wheels' measured speeds (after inertia),
  // left and right, in m/s; for the acceleration drive its turn rate (rad/s) and forward
  // speed (m/s).
  double wheel_speed_mps[2] = {0.0, 0.0};
  double displacement_m = 0.0;             // |position change| over the last control step
  double forward_displacement_m = 0.0;     // position change projected on the heading
  bool collided = false;                   // contact with a wall, an obstacle or another robot during the step
  std::uint32_t bumped = 0;                // bit i: bumper i touched during the step
  FloorState floor;                        // zones, lights' reach, sweep grid, energy
};

// The clearance a random start keeps from the walls, the obstacles and the robots placed before
// it (random_free_pose's default; the compiler sizes a group's room by it).
inline constexpr double kStartMargin_m = 0.005;

// One robot's wheel commands (or, for the acceleration drive, turn and speed), in [-1, 1].
struct DriveCommand {
  double left = 0.0;
  double right = 0.0;
};

class World {
 public:
  World(const ArenaSpec& arena, const RobotParams& robot);
  // A group: robots[i] is robot i's body. Throws std::invalid_argument for an empty group or
  // one that mixes the acceleration drive (kinematic, outside Bullet) with wheeled bodies.
  World(const ArenaSpec& arena, const std::vector<RobotParams>& robots);
  ~World();
  World(const World&) = delete;
  World& operator=(const World&) = delete;
  World(World&&) noexcept;
  World& operator=(World&&) noexcept;

  // A uniformly random pose whose body clears every wall and obstacle by `margin_m`.
  // Throws std::runtime_error if no such pose is found (the arena has no free space).
  [[nodiscard]] Pose random_free_pose(Rng& rng, double margin_m = kStartMargin_m) const;
  // For every robot in turn, a uniformly random pose whose body clears every wall and
  // obstacle, and the robots before it, by `margin_m`; robot 0 draws what random_free_pose does.
  [[nodiscard]] std::vector<Pose> random_free_poses(Rng& rng, double margin_m = kStartMargin_m) const;

  [[nodiscard]] std::size_t robots() const noexcept;

  // Where begin_epoch starts the robots from now on (formation.hpp; random by default).
  // Throws std::invalid_argument for a formation its robots cannot take: `at` poses not one
  // per robot, outside the arena, overlapping a wall, an obstacle or each other; a line or a
  // circle whose neighbours would overlap, or that cannot fit in the arena.
  void set_formation(const Formation& formation);

  // Draws a position for every zone with random_position (in zone index order: uniform
  // over the centres that keep the zone inside the arena and clear of every obstacle; see
  // docs/robot-model.md) and moves the lights above those zones with them. Draws nothing
  // when no zone is random. Zones keep their positions until the next call (reset() does
  // not move them). Throws std::runtime_error if a zone finds no free place.
  void place_zones(Rng& rng);

  // Places the robot at rest at `pose` and clears all dynamic state: motors, energy (full),
  // visited cells (the start cell only), reach flags (a light whose reach the robot starts
  // in counts only after leaving and coming back).
  void reset(const Pose& pose);
  // The same for a group: poses[i] is robot i's (as many as robots()).
  void reset(std::span<const Pose> poses);

  // The start of an epoch, in this order: place_zones(rng); robot 0's pose is the arena's
  // fixed_start, else random_free_pose(rng), and every other robot's a random pose clear of
  // those before it; reset(poses). Returns robot 0's pose. With no random zone and one robot
  // it draws exactly what `reset(fixed_start or random_free_pose(rng))` draws. A formation
  // (set_formation) places every robot instead: its `at` poses, or a line or circle about a
  // heading and then a centre drawn uniformly until every body clears the walls and obstacles
  // (a line or circle of one robot starts it as without one).
  Pose begin_epoch(Rng& rng);

  // One control step: commands in [-1, 1] (clamped), motors and body integrated over
  // physics_substeps fixed steps; the motors' speed errors drawn from `rng` when the robot
  // has motor noise (left wheel first). No allocation.
  void step(double left_command, double right_command, Rng& rng);
  // The same for a robot without motor noise, which draws nothing (tests, benchmarks);
  // throws std::logic_error for a robot with motor noise.
  void step(double left_command, double right_command);
  // A group's control step: commands[i] is robot i's; motor noise drawn robot by robot.
  void step(std::span<const DriveCommand> commands, Rng& rng);

  // IR proximity readings, 0 (nothing within range) .. 1 (touching); noise drawn from
  // `rng` when the model has noise. No allocation.
  void read_ir(std::array<double, kIrSensors>& out, Rng& rng, std::size_t robot = 0) const;

  // Ambient light readings, 0 dark .. 1 bright, from every light of the arena at its
  // position this epoch and every other robot's emission (RobotParams::emission) where that
  // robot is; noise drawn from `rng` only when robot.light.noise_sd > 0 (one draw per sensor,
  // in index order). No allocation. Other robots do not shade light.
  void read_light(std::array<double, kLightSensors>& out, Rng& rng, std::size_t robot = 0) const;

  // Rangefinder readings (rangefinder.hpp), in the order the robot declares them, into
  // out[0 .. robot().rangefinders.angles_rad.size()); nothing without rangefinders. No noise,
  // no allocation.
  void read_rangefinders(std::span<double> out, std::size_t robot = 0) const;

  // Ground sensor readings, 1 over a visible zone and 0 elsewhere, in the order the robot
  // declares them, into out[0 .. robot().ground.mounts.size()). No noise, no allocation.
  void read_ground(std::span<double> out, std::size_t robot = 0) const;

  // The goal radar slice (goal_radar.hpp) that holds the arena's goal; -1 for an arena
  // without a goal or a robot without radars.
  [[nodiscard]] int goal_slice(std::size_t robot = 0) const noexcept;

  // Where the zones' centres and the lights' floor positions are this epoch (index as in
  // the ArenaSpec), for replays.
  [[nodiscard]] std::span<const Vec2> zone_centers() const noexcept;
  [[nodiscard]] std::span<const Vec2> light_positions() const noexcept;

  // Whether `p` lies inside zone `zone` (at its position this epoch; boundary included).
  [[nodiscard]] bool in_zone(std::size_t zone, Vec2 p) const noexcept;

  // Area-sweeping grid: columns x rows of arena.sweep_cell_m cells from the lower-left
  // corner (the last column and row may be partial).
  [[nodiscard]] int sweep_columns() const noexcept;
  [[nodiscard]] int sweep_rows() const noexcept;

  [[nodiscard]] const RobotState& state(std::size_t robot = 0) const noexcept;
  [[nodiscard]] const RobotParams& robot(std::size_t robot = 0) const noexcept;
  [[nodiscard]] const ArenaSpec& arena() const noexcept;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace esc::sim
