#pragma once
// The pie-slice goal radars of Lehman & Stanley's (2011) maze navigator: the circle around
// the body split into equal slices, slice 0 centred on the heading and the others following
// counter-clockwise (4 slices: front, left, back, right, each 90 degrees wide, their source's
// [315, 405), [45, 135), [135, 225), [225, 315) degrees). The radar of the slice that holds the
// goal's bearing reads 1, the others 0 (docs/robot-model.md, "Goal radars").
#include <array>

#include "runtime/sim/arena.hpp"
#include "runtime/sim/robot_params.hpp"

namespace esc::sim {

// The slice (0 .. slices - 1) holding the bearing of `goal` seen from the robot at `pose`;
// each slice holds its clockwise edge, not its counter-clockwise one (to rounding). A goal
// at the centre itself counts as straight ahead, in slice 0. `slices` >= 1.
[[nodiscard]] int radar_slice(const Pose& pose, Vec2 goal, int slices) noexcept;

// radar_slice for a robot of `slices` radars, without its atan2 where the bearing is clear of
// every slice's edge: the goal is placed against the edges by cross products in the robot's
// frame, and only a bearing within 1e-9 rad of an edge (far beyond atan2's rounding, so the
// answer is radar_slice's wherever this decides) is left to radar_slice.
class GoalRadar {
 public:
  explicit GoalRadar(int slices) noexcept;
  // `facing`: (cos, sin) of pose.heading_rad.
  [[nodiscard]] int slice(const Pose& pose, Vec2 facing, Vec2 goal) const noexcept;

 private:
  int slices_;
  std::array<Vec2, kMaxRadars + 1> edges_{};   // slice k's clockwise edge, the first again at the end
};

}  // namespace esc::sim
