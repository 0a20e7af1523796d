#include "runtime/sim/rangefinder.hpp"

#include <array>
#include <cmath>
#include <cstddef>

namespace esc::sim {

RangefinderModel::RangefinderModel(const RobotParams& robot, const StaticGeometry2D& geometry)
    : range_m_(robot.rangefinders.range_m), geometry_(geometry), all_(geometry.everything()) {
  for (const double a : robot.rangefinders.angles_rad) {
    cos_.push_back(std::cos(a));
    sin_.push_back(std::sin(a));
  }
}

void RangefinderModel::read(const Pose& pose, std::span<double> out, std::span<const PlacedBody> others) const noexcept {
  if (!cos_.empty()) read(pose, {std::cos(pose.heading_rad), std::sin(pose.heading_rad)}, out, others);
}

void RangefinderModel::read(const Pose& pose, Vec2 facing, std::span<double> out,
                            std::span<const PlacedBody> others) const noexcept {
  const auto n = cos_.size();
  if (n == 0) return;
  const Vec2 centre{pose.x_m, pose.y_m};
  const double c = facing.x;
  const double s = facing.y;
  std::array<double, kMaxRangefinders> dx, dy, t;
  for (std::size_t i = 0; i < n; ++i) {
    dx[i] = c * cos_[i] - s * sin_[i];
    dy[i] = s * cos_[i] + c * sin_[i];
    t[i] = range_m_;
  }
  geometry_.cast_fan(all_, centre, range_m_, static_cast<int>(n), dx.data(), dy.data(), t.data());
  cast_fan_at_bodies(others, centre, static_cast<int>(n), dx.data(), dy.data(), t.data());
  for (std::size_t i = 0; i < n; ++i) out[i] = t[i] / range_m_;
}

}  // namespace esc::sim
