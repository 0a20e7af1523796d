#include "runtime/sim/ir_sensor.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>

#include "runtime/sim/validate.hpp"

namespace esc::sim {

namespace {
constexpr double kCmPerM = 100.0;
constexpr double kRadPerDeg = std::numbers::pi / 180.0;
}  // namespace

double enki_ir_curve(double distance_m) noexcept {
  const double x = distance_m * kCmPerM;
  return kEnkiIrM * (kEnkiIrC_cm2 - kEnkiIrX0_cm * kEnkiIrX0_cm) /
         (x * x - 2.0 * kEnkiIrX0_cm * x + kEnkiIrC_cm2);
}

IrModel::IrModel(const KheperaParams& robot, const StaticGeometry2D& geometry)
    : body_radius_m_(robot.body_radius_m),
      range_m_(robot.ir.range_m),
      noise_sd_(robot.ir.noise_sd),
      rays_(robot.ir.rays),
      curve_at_range_(enki_ir_curve(robot.ir.range_m)),
      curve_scale_(1.0 / (enki_ir_curve(0.0) - enki_ir_curve(robot.ir.range_m))),
      geometry_(geometry),
      near_(geometry.nearby()) {
  const auto n = static_cast<std::size_t>(8 * rays_);
  for (auto* v : {&mount_x_, &mount_y_, &dir_x_, &dir_y_}) v->resize(n);
  for (int s = 0; s < 8; ++s) {
    const double mount = kIrMountDeg[static_cast<std::size_t>(s)] * kRadPerDeg;
    const double facing = kIrFacingDeg[static_cast<std::size_t>(s)] * kRadPerDeg;
    for (int r = 0; r < rays_; ++r) {
      const double offset =
          rays_ == 1 ? 0.0 : robot.ir.aperture_rad * (static_cast<double>(r) / (rays_ - 1) - 0.5);
      const auto i = static_cast<std::size_t>(s * rays_ + r);
      mount_x_[i] = body_radius_m_ * std::cos(mount);
      mount_y_[i] = body_radius_m_ * std::sin(mount);
      dir_x_[i] = std::cos(facing + offset);
      dir_y_[i] = std::sin(facing + offset);
    }
  }
}

double IrModel::response(double distance_m) const noexcept {
  if (!(distance_m < range_m_)) return 0.0;
  const double v = (enki_ir_curve(std::max(distance_m, 0.0)) - curve_at_range_) * curve_scale_;
  return std::clamp(v, 0.0, 1.0);
}

void IrModel::read(const Pose& pose, std::array<double, 8>& out, Rng& rng) const noexcept {
  geometry_.gather({pose.x_m, pose.y_m}, body_radius_m_ + range_m_, near_);
  if (near_.empty()) {
    for (double& v : out) {
      v = response(range_m_);
      if (noise_sd_ > 0.0) v = std::clamp(v + noise_sd_ * rng.normal(), 0.0, 1.0);
    }
    return;
  }
  const double c = std::cos(pose.heading_rad);
  const double s = std::sin(pose.heading_rad);
  const auto rays = static_cast<std::size_t>(rays_);
  std::array<double, kMaxIrRays> dx, dy, t;
  for (std::size_t sensor = 0; sensor < 8; ++sensor) {
    double nearest = range_m_;
    // The rays of a sensor share its mount point.
    const std::size_t first = sensor * rays;
    const Vec2 origin{pose.x_m + c * mount_x_[first] - s * mount_y_[first],
                      pose.y_m + s * mount_x_[first] + c * mount_y_[first]};
    if (geometry_.fan_meets_any(near_, origin, range_m_)) {
      for (std::size_t r = 0; r < rays; ++r) {
        dx[r] = c * dir_x_[first + r] - s * dir_y_[first + r];
        dy[r] = s * dir_x_[first + r] + c * dir_y_[first + r];
        t[r] = range_m_;
      }
      geometry_.cast_fan(near_, origin, range_m_, rays_, dx.data(), dy.data(), t.data());
      for (std::size_t r = 0; r < rays; ++r) nearest = std::min(nearest, t[r]);
    }
    double v = response(nearest);
    if (noise_sd_ > 0.0) v = std::clamp(v + noise_sd_ * rng.normal(), 0.0, 1.0);
    out[sensor] = v;
  }
}

}  // namespace esc::sim
