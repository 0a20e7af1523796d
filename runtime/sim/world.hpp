#pragma once
// One Bullet world holding an arena and one Khepera. A worker builds a World once and
// reuses it for every evaluation: reset() returns it to a state indistinguishable from a
// freshly built world (body state, contact manifolds, broadphase pairs, solver seed), so a
// trajectory depends only on its start pose, its commands and its noise stream, never on
// what the world simulated before.
#include <array>
#include <memory>

#include "runtime/core/rng.hpp"
#include "runtime/sim/arena.hpp"
#include "runtime/sim/khepera_params.hpp"

namespace esc::sim {

inline constexpr int kIrSensors = 8;

// Physical state after the last control step; what observables are computed from.
struct RobotState {
  Pose pose;
  double wheel_speed_mps[2] = {0.0, 0.0};  // measured (after inertia), left and right
  double displacement_m = 0.0;             // |position change| over the last control step
  double forward_displacement_m = 0.0;     // position change projected on the heading
  bool collided = false;                   // contact with a wall or obstacle during the step
};

class World {
 public:
  World(const ArenaSpec& arena, const KheperaParams& robot);
  ~World();
  World(const World&) = delete;
  World& operator=(const World&) = delete;
  World(World&&) noexcept;
  World& operator=(World&&) noexcept;

  // A uniformly random pose whose body clears every wall and obstacle by `margin_m`.
  // Throws std::runtime_error if no such pose is found (the arena has no free space).
  [[nodiscard]] Pose random_free_pose(Rng& rng, double margin_m = 0.005) const;

  // Places the robot at rest at `pose` and clears all dynamic state.
  void reset(const Pose& pose);

  // One control step: commands in [-1, 1] (clamped), motors and body integrated over
  // physics_substeps fixed steps. No allocation.
  void step(double left_command, double right_command);

  // IR proximity readings, 0 (nothing within range) .. 1 (touching); noise drawn from
  // `rng` when the model has noise. No allocation.
  void read_ir(std::array<double, kIrSensors>& out, Rng& rng) const;

  [[nodiscard]] const RobotState& state() const noexcept;
  [[nodiscard]] const KheperaParams& robot() const noexcept;
  [[nodiscard]] const ArenaSpec& arena() const noexcept;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace esc::sim
