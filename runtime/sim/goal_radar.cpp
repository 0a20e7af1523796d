#include "runtime/sim/goal_radar.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace esc::sim {

int radar_slice(const Pose& pose, Vec2 goal, int slices) noexcept {
  const double dx = goal.x - pose.x_m;
  const double dy = goal.y - pose.y_m;
  if (dx == 0.0 && dy == 0.0) return 0;
  const double width = 2 * std::numbers::pi / slices;
  // The bearing from the heading, turned by half a slice so that slice k spans
  // [k width, (k + 1) width), then brought into [0, 2 pi).
  double a = std::atan2(dy, dx) - pose.heading_rad + width / 2;
  a -= 2 * std::numbers::pi * std::floor(a / (2 * std::numbers::pi));
  return std::clamp(static_cast<int>(a / width), 0, slices - 1);
}

}  // namespace esc::sim
