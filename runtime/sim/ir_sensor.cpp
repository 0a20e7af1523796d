#include "runtime/sim/ir_sensor.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "runtime/sim/validate.hpp"

namespace esc::sim {

namespace {
constexpr double kCmPerM = 100.0;
}  // namespace

double enki_ir_curve(double distance_m, double x0_cm, double c_cm2) noexcept {
  const double x = distance_m * kCmPerM;
  return kEnkiIrM * (c_cm2 - x0_cm * x0_cm) / (x * x - 2.0 * x0_cm * x + c_cm2);
}

Vec2 mount_point(const IrMount& m, double body_radius_m) noexcept {
  return polar(m.bearing_rad, m.radius_m.value_or(body_radius_m));
}

IrResponse::IrResponse(const IrParams& ir)
    : range_m_(ir.range_m),
      x0_cm_(ir.curve_x0_cm),
      c_cm2_(ir.curve_c_cm2),
      peak_m_(std::max(x0_cm_, 0.0) / kCmPerM),
      curve_at_range_(enki_ir_curve(ir.range_m, x0_cm_, c_cm2_)),
      curve_scale_(1.0 / (enki_ir_curve(peak_m_, x0_cm_, c_cm2_) - curve_at_range_)),
      table_(ir.response) {}

double IrResponse::operator()(double distance_m) const noexcept {
  if (!(distance_m < range_m_)) return 0.0;
  if (table_.empty())
    return std::clamp((enki_ir_curve(std::max(distance_m, peak_m_), x0_cm_, c_cm2_) - curve_at_range_) * curve_scale_,
                      0.0, 1.0);
  const double d = std::max(distance_m, 0.0);
  // Flat before the first point and after the last (validated: distances increase).
  const auto after = std::upper_bound(table_.begin(), table_.end(), d,
                                      [](double x, const IrResponsePoint& p) { return x < p.distance_m; });
  if (after == table_.begin()) return table_.front().reading;
  if (after == table_.end()) return table_.back().reading;
  const IrResponsePoint& a = *(after - 1);
  const double f = (d - a.distance_m) / (after->distance_m - a.distance_m);
  return std::clamp(a.reading + f * (after->reading - a.reading), 0.0, 1.0);
}

IrModel::IrModel(const RobotParams& robot, const StaticGeometry2D& geometry)
    : body_radius_m_(robot.body_radius_m),
      range_m_(robot.ir.range_m),
      noise_sd_(robot.ir.noise_sd),
      rays_(robot.ir.rays),
      sensors_(static_cast<int>(robot.ir.mounts.size())),
      response_(robot.ir),
      geometry_(geometry),
      near_(geometry.nearby()) {
  const auto n = static_cast<std::size_t>(sensors_ * rays_);
  for (auto* v : {&mount_x_, &mount_y_, &dir_x_, &dir_y_}) v->resize(n);
  for (int s = 0; s < sensors_; ++s) {
    const IrMount& m = robot.ir.mounts[static_cast<std::size_t>(s)];
    const Vec2 mount = mount_point(m, body_radius_m_);
    for (int r = 0; r < rays_; ++r) {
      const double offset =
          rays_ == 1 ? 0.0 : robot.ir.aperture_rad * (static_cast<double>(r) / (rays_ - 1) - 0.5);
      const auto i = static_cast<std::size_t>(s * rays_ + r);
      mount_x_[i] = mount.x;
      mount_y_[i] = mount.y;
      dir_x_[i] = std::cos(m.facing_rad + offset);
      dir_y_[i] = std::sin(m.facing_rad + offset);
    }
  }
}

void IrModel::read(const Pose& pose, std::array<double, 8>& out, Rng& rng,
                   std::span<const PlacedBody> others) const noexcept {
  const auto sensors = static_cast<std::size_t>(sensors_);
  std::fill(out.begin() + static_cast<std::ptrdiff_t>(sensors), out.end(), 0.0);
  if (sensors == 0) return;  // the navigator: no search of the arena, no draw
  geometry_.gather({pose.x_m, pose.y_m}, body_radius_m_ + range_m_, near_);
  if (near_.empty() && others.empty()) {
    for (std::size_t sensor = 0; sensor < sensors; ++sensor) {
      double& v = out[sensor];
      v = response(range_m_);
      if (noise_sd_ > 0.0) v = std::clamp(v + noise_sd_ * rng.normal(), 0.0, 1.0);
    }
    return;
  }
  const double c = std::cos(pose.heading_rad);
  const double s = std::sin(pose.heading_rad);
  const auto rays = static_cast<std::size_t>(rays_);
  std::array<double, kMaxIrRays> dx, dy, t;
  for (std::size_t sensor = 0; sensor < sensors; ++sensor) {
    double nearest = range_m_;
    // The rays of a sensor share its mount point.
    const std::size_t first = sensor * rays;
    const Vec2 origin{pose.x_m + c * mount_x_[first] - s * mount_y_[first],
                      pose.y_m + s * mount_x_[first] + c * mount_y_[first]};
    if (!others.empty() || geometry_.fan_meets_any(near_, origin, range_m_)) {
      for (std::size_t r = 0; r < rays; ++r) {
        dx[r] = c * dir_x_[first + r] - s * dir_y_[first + r];
        dy[r] = s * dir_x_[first + r] + c * dir_y_[first + r];
        t[r] = range_m_;
      }
      geometry_.cast_fan(near_, origin, range_m_, rays_, dx.data(), dy.data(), t.data());
      cast_fan_at_bodies(others, origin, rays_, dx.data(), dy.data(), t.data());
      for (std::size_t r = 0; r < rays; ++r) nearest = std::min(nearest, t[r]);
    }
    double v = response(nearest);
    if (noise_sd_ > 0.0) v = std::clamp(v + noise_sd_ * rng.normal(), 0.0, 1.0);
    out[sensor] = v;
  }
}

}  // namespace esc::sim
