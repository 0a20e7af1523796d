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

GoalRadar::GoalRadar(int slices) noexcept : slices_(std::clamp(slices, 1, kMaxRadars)) {
  const double width = 2 * std::numbers::pi / slices_;
  for (int k = 0; k <= slices_; ++k) edges_[k] = {std::cos(k * width - width / 2), std::sin(k * width - width / 2)};
}

int GoalRadar::slice(const Pose& pose, Vec2 facing, Vec2 goal) const noexcept {
  if (slices_ == 1) return 0;
  const double dx = goal.x - pose.x_m;
  const double dy = goal.y - pose.y_m;
  // The goal in the robot's frame; |fx| + |fy| bounds its length from above.
  const double fx = dx * facing.x + dy * facing.y;
  const double fy = -dx * facing.y + dy * facing.x;
  const double margin = 1e-9 * (std::abs(fx) + std::abs(fy));
  // Slice k holds the bearings counter-clockwise of edge k and clockwise of edge k + 1; with
  // slices of at most half a turn, one k at most has both, each by more than the margin.
  double before = edges_[0].x * fy - edges_[0].y * fx;
  for (int k = 0; k < slices_; ++k) {
    const double after = edges_[k + 1].x * fy - edges_[k + 1].y * fx;
    if (before > margin && after < -margin) return k;
    before = after;
  }
  return radar_slice(pose, goal, slices_);
}

}  // namespace esc::sim
