#pragma once
// The pie-slice goal radars of Lehman & Stanley's (2011) maze navigator: the circle around
// the body split into equal slices, slice 0 centred on the heading and the others following
// counter-clockwise (4 slices: front, left, back, right, each 90 degrees wide, their source's
// [315, 405), [45, 135), [135, 225), [225, 315) degrees). The radar of the slice that holds the
// goal's bearing reads 1, the others 0 (docs/robot-model.md, "Goal radars").
#include "runtime/sim/arena.hpp"

namespace esc::sim {

// The slice (0 .. slices - 1) holding the bearing of `goal` seen from the robot at `pose`;
// each slice holds its clockwise edge, not its counter-clockwise one (to rounding). A goal
// at the centre itself counts as straight ahead, in slice 0. `slices` >= 1.
[[nodiscard]] int radar_slice(const Pose& pose, Vec2 goal, int slices) noexcept;

}  // namespace esc::sim
