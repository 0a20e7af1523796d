#pragma once
// The rangefinders of Lehman & Stanley's (2011) maze navigator, on the Khepera: rays from the
// body's centre at fixed angles from the heading, each reading the distance to the first wall
// or obstacle along it over its range, or 1 when none is within range (the navigator's network
// reads distance / range). Exact ray casts in the arena's 2D geometry; no noise
// (docs/robot-model.md, "Rangefinders").
#include <span>
#include <vector>

#include "runtime/sim/arena.hpp"
#include "runtime/sim/geometry2d.hpp"
#include "runtime/sim/neighbours.hpp"
#include "runtime/sim/robot_params.hpp"

namespace esc::sim {

class RangefinderModel {
 public:
  // `geometry` is the arena's and must outlive the model.
  RangefinderModel(const RobotParams& robot, const StaticGeometry2D& geometry);

  // The readings of the robot at `pose`, in the order the robot declares its rangefinders,
  // into out[0 .. count()); `out` holds at least count() values. No allocation; a robot
  // without rangefinders casts nothing.
  // `others`: the bodies of the other robots of a group that may be within range.
  void read(const Pose& pose, std::span<double> out, std::span<const PlacedBody> others = {}) const noexcept;
  // The same with the heading's (cos, sin) already known.
  void read(const Pose& pose, Vec2 facing, std::span<double> out, std::span<const PlacedBody> others = {}) const noexcept;

  [[nodiscard]] int count() const noexcept { return static_cast<int>(cos_.size()); }

 private:
  double range_m_;
  const StaticGeometry2D& geometry_;
  std::vector<double> cos_, sin_;            // each ray's direction in the body frame
  StaticGeometry2D::Nearby all_;             // cast_fan culls them by the rays' reach
};

}  // namespace esc::sim
