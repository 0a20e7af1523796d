#include "runtime/sim/light_sensor.hpp"

#include <algorithm>
#include <cmath>

#include "runtime/sim/ir_sensor.hpp"

namespace esc::sim {

LightModel::LightModel(const RobotParams& robot)
    : body_radius_m_(robot.body_radius_m),
      inv_half_distance2_(1.0 / (robot.light.half_distance_m * robot.light.half_distance_m)),
      noise_sd_(robot.light.noise_sd),
      sensors_(robot.ir.mounts.size()) {
  for (std::size_t s = 0; s < sensors_; ++s) {
    const IrMount& m = robot.ir.mounts[s];
    const Vec2 mount = mount_point(m, body_radius_m_);
    mount_x_[s] = mount.x;
    mount_y_[s] = mount.y;
    face_x_[s] = std::cos(m.facing_rad);
    face_y_[s] = std::sin(m.facing_rad);
  }
}

double LightModel::response(double intensity, double distance_m,
                            double cos_incidence) const noexcept {
  if (!(cos_incidence > 0.0)) return 0.0;
  return intensity * cos_incidence / (1.0 + distance_m * distance_m * inv_half_distance2_);
}

void LightModel::read(const Pose& pose, const StaticGeometry2D& geometry,
                      const PlacedLight* lights, std::size_t n,
                      std::array<double, kLightSensors>& out, Rng& rng) const noexcept {
  out.fill(0.0);
  if (n == 0 && !(noise_sd_ > 0.0)) return;   // dark, and no noise to draw
  if (n > 0) {
    const double c = std::cos(pose.heading_rad);
    const double s = std::sin(pose.heading_rad);
    std::array<double, kLightSensors> px{}, py{}, fx{}, fy{};
    for (std::size_t i = 0; i < sensors_; ++i) {
      px[i] = pose.x_m + c * mount_x_[i] - s * mount_y_[i];
      py[i] = pose.y_m + s * mount_x_[i] + c * mount_y_[i];
      fx[i] = c * face_x_[i] - s * face_y_[i];
      fy[i] = s * face_x_[i] + c * face_y_[i];
    }
    // Per light: the lit sensors' contributions, then one batch of occlusion rays from
    // those sensors to the light's floor position (walls and obstacles are taller than
    // any light, so the test is planar).
    std::array<double, kLightSensors> gain{}, ox{}, oy{}, dx{}, dy{}, t{}, len{};
    std::array<std::size_t, kLightSensors> who{};
    for (std::size_t l = 0; l < n; ++l) {
      const PlacedLight& light = lights[l];
      const double h2 = light.height_m * light.height_m;
      int rays = 0;
      for (std::size_t i = 0; i < sensors_; ++i) {
        const double ex = light.x_m - px[i];
        const double ey = light.y_m - py[i];
        const double floor2 = ex * ex + ey * ey;
        const double dist = std::sqrt(floor2 + h2);
        // A light exactly at the sensor: head-on at distance 0.
        const double cos_inc = dist > 0.0 ? (fx[i] * ex + fy[i] * ey) / dist : 1.0;
        const double g = response(light.intensity, dist, cos_inc);
        if (!(g > 0.0)) continue;
        const double floor_dist = std::sqrt(floor2);
        if (floor_dist == 0.0) {  // the light is straight above the sensor
          out[i] += g;
          continue;
        }
        const auto k = static_cast<std::size_t>(rays++);
        who[k] = i;
        gain[k] = g;
        ox[k] = px[i];
        oy[k] = py[i];
        dx[k] = ex / floor_dist;
        dy[k] = ey / floor_dist;
        t[k] = floor_dist;
        len[k] = floor_dist;
      }
      if (rays == 0) continue;
      const double reach =
          body_radius_m_ + std::hypot(light.x_m - pose.x_m, light.y_m - pose.y_m);
      geometry.cast_rays({pose.x_m, pose.y_m}, reach, rays, ox.data(), oy.data(), dx.data(),
                         dy.data(), t.data());
      for (std::size_t k = 0; k < static_cast<std::size_t>(rays); ++k)
        if (t[k] >= len[k] - kLightOcclusionTolerance_m) out[who[k]] += gain[k];
    }
  }
  for (std::size_t i = 0; i < sensors_; ++i) {
    double& v = out[i];
    v = std::min(v, 1.0);
    if (noise_sd_ > 0.0) v = std::clamp(v + noise_sd_ * rng.normal(), 0.0, 1.0);
  }
}

}  // namespace esc::sim
