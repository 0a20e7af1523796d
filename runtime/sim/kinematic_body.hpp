#pragma once
// Lehman & Stanley's maze navigator in motion (their novelty-search-cpp maze.h, Character and
// Update), the acceleration drive of robot_params.hpp: plain C++, no Bullet. At each control
// step of dt the first command changes the turn rate by command * max_turn_accel * dt and the
// second the forward speed by command * max_accel * dt, each clamped to its top; the centre
// then moves by speed * dt along the heading the step began with while the heading turns by
// rate * dt; a move that would bring the centre within the body's radius of a wall or an
// obstacle is cancelled (the centre stays, the heading and both speeds are kept), as theirs.
#include "runtime/sim/arena.hpp"
#include "runtime/sim/geometry2d.hpp"
#include "runtime/sim/neighbours.hpp"
#include "runtime/sim/robot_params.hpp"

namespace esc::sim {

class KinematicBody {
 public:
  explicit KinematicBody(const RobotParams& robot) noexcept;

  // At rest at `pose`.
  void place(const Pose& pose) noexcept;

  // One control step (commands clamped to [-1, 1], NaN as 0); false when the move was cancelled.
  // `others`: the other robots of a group that may be within reach, whose bodies (their
  // bounding discs) cancel a move as walls do.
  [[nodiscard]] bool move(double turn_command, double speed_command, const StaticGeometry2D& geometry,
                          std::span<const PlacedBody> others = {}) noexcept;

  [[nodiscard]] const Pose& pose() const noexcept { return pose_; }
  // (cos, sin) of the pose's heading, computed once per move for the move, the step's
  // displacement and the rangefinders: the same values each would compute.
  [[nodiscard]] Vec2 facing() const noexcept { return facing_; }
  // Where the last move would have taken the centre (where it went, unless cancelled).
  [[nodiscard]] Vec2 attempted() const noexcept { return attempted_; }
  [[nodiscard]] double turn_radps() const noexcept { return turn_radps_; }
  [[nodiscard]] double speed_mps() const noexcept { return speed_mps_; }

 private:
  double radius_m_;
  double dt_s_;
  double max_speed_mps_, speed_step_mps_;      // the top speed; its change at command 1 in one step
  double max_turn_radps_, turn_step_radps_;    // the top turn rate; its change at command 1 in one step
  Pose pose_;
  Vec2 facing_;
  Vec2 attempted_;
  double speed_mps_ = 0.0;
  double turn_radps_ = 0.0;
};

}  // namespace esc::sim
