#include "bench/plain_world.hpp"

#include <cmath>
#include <numbers>

namespace esc::bench::plain {

namespace {

constexpr double kPi = std::numbers::pi;
// The Khepera's sensors: mount angle on the perimeter and facing, degrees from the heading.
constexpr double kMountDeg[8] = {68, 43, 13, -13, -43, -68, 158, -158};
constexpr double kFacingDeg[8] = {90, 45, 10, -10, -45, -90, 180, 180};

// Enki's IR curve, distance in cm.
double enki(double d_m) {
  const double x = d_m * 100;
  return 1200 * (7 - 0.81) / (x * x + 1.8 * x + 7);
}

}  // namespace

World::World(const Setup& s)
    : s_(s),
      decay_(std::exp(-s.control_step_s / s.substeps / s.time_constant_s)),
      max_delta_mps_(s.max_accel_mps2 * s.control_step_s / s.substeps),
      dt_s_(s.control_step_s / s.substeps),
      curve_range_(enki(s.ir_range_m)),
      curve_scale_(1 / (enki(0) - enki(s.ir_range_m))) {
  for (int i = 0; i < 8; ++i) {
    const double mount = kMountDeg[i] * kPi / 180;
    const double facing = kFacingDeg[i] * kPi / 180;
    mount_x_[i] = s.radius_m * std::cos(mount);
    mount_y_[i] = s.radius_m * std::sin(mount);
    face_x_[i] = std::cos(facing);
    face_y_[i] = std::sin(facing);
    for (int k = 0; k < s.ir_rays; ++k) {
      const double off = s.ir_rays == 1 ? 0 : s.ir_aperture_rad * (double(k) / (s.ir_rays - 1) - 0.5);
      ray_x_.push_back(mount_x_[i]);
      ray_y_.push_back(mount_y_[i]);
      dir_x_.push_back(std::cos(facing + off));
      dir_y_.push_back(std::sin(facing + off));
    }
  }
}

double World::clearance(double x, double y) const {
  double d = std::min(std::min(x, s_.width_m - x), std::min(y, s_.height_m - y));
  for (const Circle& c : s_.cylinders) {
    const double dx = x - c.x_m, dy = y - c.y_m;
    d = std::min(d, std::sqrt(dx * dx + dy * dy) - c.r_m);
  }
  return d;
}

Robot World::random_start(std::mt19937_64& rng) const {
  const double keep = s_.radius_m + 0.005;
  std::uniform_real_distribution<double> ux(keep, s_.width_m - keep), uy(keep, s_.height_m - keep), uh(-kPi, kPi);
  Robot r;
  do {
    r.x_m = ux(rng);
    r.y_m = uy(rng);
  } while (clearance(r.x_m, r.y_m) < keep);
  r.heading_rad = uh(rng);
  return r;
}

void World::place_zone(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> ux(s_.zone_radius_m, s_.width_m - s_.zone_radius_m),
      uy(s_.zone_radius_m, s_.height_m - s_.zone_radius_m);
  zone_x_ = ux(rng);
  zone_y_ = uy(rng);
}

bool World::in_zone(const Robot& r) const {
  const double dx = r.x_m - zone_x_, dy = r.y_m - zone_y_;
  return dx * dx + dy * dy <= s_.zone_radius_m * s_.zone_radius_m;
}

bool World::step(Robot& r, double left_command, double right_command, Accumulator* energy) const {
  const double target_l = std::clamp(left_command, -1.0, 1.0) * s_.max_speed_mps;
  const double target_r = std::clamp(right_command, -1.0, 1.0) * s_.max_speed_mps;
  bool touched = false;
  for (int i = 0; i < s_.substeps; ++i) {
    r.left_mps += std::clamp(target_l + (r.left_mps - target_l) * decay_ - r.left_mps, -max_delta_mps_, max_delta_mps_);
    r.right_mps += std::clamp(target_r + (r.right_mps - target_r) * decay_ - r.right_mps, -max_delta_mps_, max_delta_mps_);
    const double v = 0.5 * (r.left_mps + r.right_mps);
    const double w = (r.right_mps - r.left_mps) / s_.wheel_base_m;
    const double half_turn = 0.5 * w * dt_s_;
    const double chord = half_turn == 0 ? v : v * std::sin(half_turn) / half_turn;
    r.x_m += chord * dt_s_ * std::cos(r.heading_rad + half_turn);
    r.y_m += chord * dt_s_ * std::sin(r.heading_rad + half_turn);
    r.heading_rad += w * dt_s_;
    if (clearance(r.x_m, r.y_m) <= s_.radius_m + 1e-4) touched = true;
    if (energy != nullptr) {
      r.x_m = std::clamp(r.x_m, s_.radius_m, s_.width_m - s_.radius_m);
      r.y_m = std::clamp(r.y_m, s_.radius_m, s_.height_m - s_.radius_m);
      energy->substep(in_zone(r));
    }
  }
  return touched;
}

void World::read_ir(const Robot& r, double out[8]) const {
  // Only the walls and cylinders that a ray can reach from where the robot stands.
  const double reach = s_.radius_m + s_.ir_range_m;
  const bool left = r.x_m < reach, right = s_.width_m - r.x_m < reach;
  const bool bottom = r.y_m < reach, top = s_.height_m - r.y_m < reach;
  const Circle* near[8];
  int n = 0;
  for (const Circle& cy : s_.cylinders) {
    const double dx = r.x_m - cy.x_m, dy = r.y_m - cy.y_m;
    if (n < 8 && dx * dx + dy * dy < (reach + cy.r_m) * (reach + cy.r_m)) near[n++] = &cy;
  }
  if (!(left || right || bottom || top || n > 0)) {
    std::fill(out, out + 8, 0.0);
    return;
  }
  const double c = std::cos(r.heading_rad), s = std::sin(r.heading_rad);
  const int rays = s_.ir_rays;
  for (int i = 0; i < 8; ++i) {
    double nearest = s_.ir_range_m;
    for (int k = i * rays; k < (i + 1) * rays; ++k) {
      const double ox = r.x_m + c * ray_x_[k] - s * ray_y_[k];
      const double oy = r.y_m + s * ray_x_[k] + c * ray_y_[k];
      const double dx = c * dir_x_[k] - s * dir_y_[k];
      const double dy = s * dir_x_[k] + c * dir_y_[k];
      // Walls: where the ray leaves the rectangle.
      if (right && dx > 0) nearest = std::min(nearest, (s_.width_m - ox) / dx);
      if (left && dx < 0) nearest = std::min(nearest, -ox / dx);
      if (top && dy > 0) nearest = std::min(nearest, (s_.height_m - oy) / dy);
      if (bottom && dy < 0) nearest = std::min(nearest, -oy / dy);
      for (int j = 0; j < n; ++j) {
        const double px = ox - near[j]->x_m, py = oy - near[j]->y_m;
        const double b = px * dx + py * dy;
        const double disc = b * b - (px * px + py * py - near[j]->r_m * near[j]->r_m);
        if (b < 0 && disc >= 0) nearest = std::min(nearest, -b - std::sqrt(disc));
      }
    }
    nearest = std::max(nearest, 0.0);
    out[i] = nearest < s_.ir_range_m ? std::clamp((enki(nearest) - curve_range_) * curve_scale_, 0.0, 1.0) : 0.0;
  }
}

void World::read_light(const Robot& r, double out[8]) const {
  const double c = std::cos(r.heading_rad), s = std::sin(r.heading_rad);
  const double h2 = s_.light_height_m * s_.light_height_m;
  for (int i = 0; i < 8; ++i) {
    const double px = r.x_m + c * mount_x_[i] - s * mount_y_[i];
    const double py = r.y_m + s * mount_x_[i] + c * mount_y_[i];
    const double fx = c * face_x_[i] - s * face_y_[i];
    const double fy = s * face_x_[i] + c * face_y_[i];
    const double ex = zone_x_ - px, ey = zone_y_ - py;
    const double dist = std::sqrt(ex * ex + ey * ey + h2);
    const double cos_inc = (fx * ex + fy * ey) / dist;
    double v = cos_inc > 0 ? cos_inc / (1 + dist * dist / (s_.light_half_distance_m * s_.light_half_distance_m)) : 0;
    // Occluded by a cylinder between the sensor and the light's floor point.
    const double len = std::sqrt(ex * ex + ey * ey);
    for (const Circle& cy : s_.cylinders) {
      const double qx = px - cy.x_m, qy = py - cy.y_m;
      const double b = (qx * ex + qy * ey) / len;
      const double disc = b * b - (qx * qx + qy * qy - cy.r_m * cy.r_m);
      if (b < 0 && disc >= 0 && -b - std::sqrt(disc) < len) v = 0;
    }
    out[i] = std::min(v, 1.0);
  }
}

double World::forward_term(const Robot& before, const Robot& after) const {
  const double full_step_m = s_.max_speed_mps * s_.control_step_s;
  const double forward = ((after.x_m - before.x_m) * std::cos(before.heading_rad) +
                          (after.y_m - before.y_m) * std::sin(before.heading_rad)) / full_step_m;
  const double wheel_diff = std::abs(after.left_mps - after.right_mps) / (2 * s_.max_speed_mps);
  return std::max(forward, 0.0) * (1 - std::sqrt(wheel_diff));
}

}  // namespace esc::bench::plain
