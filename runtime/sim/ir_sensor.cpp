#include "runtime/sim/ir_sensor.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>

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

IrModel::IrModel(const KheperaParams& robot)
    : body_radius_m_(robot.body_radius_m),
      range_m_(robot.ir.range_m),
      noise_sd_(robot.ir.noise_sd),
      rays_(robot.ir.rays),
      curve_at_range_(enki_ir_curve(robot.ir.range_m)),
      curve_scale_(1.0 / (enki_ir_curve(0.0) - enki_ir_curve(robot.ir.range_m))) {
  const auto n = static_cast<std::size_t>(8 * rays_);
  for (auto* v : {&mount_x_, &mount_y_, &dir_x_, &dir_y_}) v->resize(n);
  for (auto* v : {&ox_, &oy_, &dx_, &dy_, &t_}) v->resize(n);
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

void IrModel::read(const Pose& pose, const StaticGeometry2D& geometry,
                   std::array<double, 8>& out, Rng& rng) const noexcept {
  const double c = std::cos(pose.heading_rad);
  const double s = std::sin(pose.heading_rad);
  const int n = 8 * rays_;
  for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i) {
    ox_[i] = pose.x_m + c * mount_x_[i] - s * mount_y_[i];
    oy_[i] = pose.y_m + s * mount_x_[i] + c * mount_y_[i];
    dx_[i] = c * dir_x_[i] - s * dir_y_[i];
    dy_[i] = s * dir_x_[i] + c * dir_y_[i];
    t_[i] = range_m_;
  }
  geometry.cast_rays({pose.x_m, pose.y_m}, body_radius_m_ + range_m_, n, ox_.data(), oy_.data(),
                     dx_.data(), dy_.data(), t_.data());
  for (std::size_t sensor = 0; sensor < 8; ++sensor) {
    double nearest = range_m_;
    for (int r = 0; r < rays_; ++r)
      nearest = std::min(nearest, t_[sensor * static_cast<std::size_t>(rays_) + static_cast<std::size_t>(r)]);
    double v = response(nearest);
    if (noise_sd_ > 0.0) v = std::clamp(v + noise_sd_ * rng.normal(), 0.0, 1.0);
    out[sensor] = v;
  }
}

}  // namespace esc::sim
