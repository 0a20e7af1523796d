#pragma once
// Shared fixtures of the sim suites: arenas, robots, and an independent 2D clearance.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "runtime/sim/world.hpp"

namespace esc::sim::test {

inline ArenaSpec empty_arena(double w, double h) {
  ArenaSpec a;
  a.width_m = w;
  a.height_m = h;
  return a;
}

// What a homing arena adds: a recharge zone placed at random with a light above it, a
// visible rectangular mark, and a second light standing free.
struct HomingFeatures {
  double recharge_radius_m;
  Vec2 mark_center_m;
  Vec2 mark_size_m;
  double light_height_m;
  LightSource free_light;
};

inline void add_homing_features(ArenaSpec& a, const HomingFeatures& f) {
  Zone recharge;
  recharge.radius_m = f.recharge_radius_m;
  recharge.random_position = true;
  recharge.recharge = true;
  a.zones.push_back(recharge);
  Zone mark;
  mark.shape = ZoneShape::Rectangle;
  mark.center_m = f.mark_center_m;
  mark.size_m = f.mark_size_m;
  mark.visible = true;
  a.zones.push_back(mark);
  LightSource above;
  above.above_zone = static_cast<int>(a.zones.size()) - 2;
  above.height_m = f.light_height_m;
  a.lights.push_back(above);
  a.lights.push_back(f.free_light);
}

// A Thymio II as lib/thymio2.esc declares it: its outline (a front arc of 8 cm about the
// axle over +-asin(5.5 / 8), the back 3 cm behind it, counter-clockwise) and its drive.
inline std::vector<Vec2> thymio_outline() {
  std::vector<Vec2> v = {{-0.03, -0.055}};
  const double a = std::asin(5.5 / 8);
  for (int i = 0; i <= 10; ++i) {
    const double t = -a + 2 * a * i / 10;
    v.push_back({0.08 * std::cos(t) * (1 - 1e-9), 0.08 * std::sin(t) * (1 - 1e-9)});
  }
  v.push_back({-0.03, 0.055});
  return v;
}

inline RobotParams thymio_like() {
  RobotParams r;
  r.outline = thymio_outline();
  r.body_radius_m = 0.08;
  r.body_height_m = 0.051;
  r.mass_kg = 0.2;
  r.wheel_base_m = 0.094;
  r.motor.max_speed_mps = 0.166;
  r.motor.inertia = false;
  r.physics_substeps = 6;
  return r;
}

inline RobotParams robot_with_inertia(bool inertia) {
  RobotParams r;
  r.motor.inertia = inertia;
  return r;
}

// Smallest signed distance from `p` to the arena's obstacles (not the walled rectangle),
// written independently of the library; a large value when there are none.
inline double obstacle_clearance(const ArenaSpec& a, double x, double y) {
  double d = 1e9;
  for (const auto& c : a.cylinders)
    d = std::min(d, std::hypot(x - c.center_m.x, y - c.center_m.y) - c.radius_m);
  for (const auto& b : a.boxes) {
    const double cs = std::cos(-b.angle_rad);
    const double sn = std::sin(-b.angle_rad);
    const double lx = cs * (x - b.center_m.x) - sn * (y - b.center_m.y);
    const double ly = sn * (x - b.center_m.x) + cs * (y - b.center_m.y);
    const double qx = std::abs(lx) - b.size_m.x / 2;
    const double qy = std::abs(ly) - b.size_m.y / 2;
    const double out = std::hypot(std::max(qx, 0.0), std::max(qy, 0.0));
    d = std::min(d, out + std::min(std::max(qx, qy), 0.0));
  }
  // A segment wall: along the segment from its midpoint (u) and across it (v), in units of
  // its length and of its half thickness.
  for (const auto& w : a.walls) {
    const double ex = w.to_m.x - w.from_m.x, ey = w.to_m.y - w.from_m.y;
    const double length = std::hypot(ex, ey);
    const double px = x - (w.from_m.x + w.to_m.x) / 2, py = y - (w.from_m.y + w.to_m.y) / 2;
    const double u = std::abs(px * ex + py * ey) / length - length / 2;
    const double v = std::abs(px * ey - py * ex) / length - w.thickness_m / 2;
    const double out = std::hypot(std::max(u, 0.0), std::max(v, 0.0));
    d = std::min(d, out + std::min(std::max(u, v), 0.0));
  }
  return d;
}

// Smallest signed distance from `p` to the arena's walls and obstacles.
inline double clearance(const ArenaSpec& a, double x, double y) {
  return std::min({x, a.width_m - x, y, a.height_m - y, obstacle_clearance(a, x, y)});
}

inline double wrap_angle(double a) {
  while (a >= std::numbers::pi) a -= 2 * std::numbers::pi;
  while (a < -std::numbers::pi) a += 2 * std::numbers::pi;
  return a;
}

}  // namespace esc::sim::test
