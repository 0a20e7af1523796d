#include "runtime/sim/kinematic_body.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace esc::sim {

namespace {

double command(double c) noexcept { return std::isnan(c) ? 0.0 : std::clamp(c, -1.0, 1.0); }

}  // namespace

KinematicBody::KinematicBody(const RobotParams& robot) noexcept
    : radius_m_(robot.body_radius_m),
      dt_s_(robot.control_step_s),
      max_speed_mps_(robot.motor.max_speed_mps),
      speed_step_mps_(robot.motor.max_accel_mps2 * robot.control_step_s),
      max_turn_radps_(robot.turn.max_rate_radps),
      turn_step_radps_(robot.turn.max_accel_radps2 * robot.control_step_s) {}

void KinematicBody::place(const Pose& pose) noexcept {
  pose_ = pose;
  facing_ = {std::cos(pose.heading_rad), std::sin(pose.heading_rad)};
  speed_mps_ = 0.0;
  turn_radps_ = 0.0;
}

bool KinematicBody::move(double turn_command, double speed_command, const StaticGeometry2D& geometry,
                         std::span<const PlacedBody> others) noexcept {
  turn_radps_ = std::clamp(turn_radps_ + command(turn_command) * turn_step_radps_, -max_turn_radps_, max_turn_radps_);
  speed_mps_ = std::clamp(speed_mps_ + command(speed_command) * speed_step_mps_, -max_speed_mps_, max_speed_mps_);
  const Vec2 next{pose_.x_m + facing_.x * speed_mps_ * dt_s_, pose_.y_m + facing_.y * speed_mps_ * dt_s_};
  attempted_ = next;
  // Headings in (-pi, pi], as the observable `heading` reads them.
  pose_.heading_rad = std::remainder(pose_.heading_rad + turn_radps_ * dt_s_, 2 * std::numbers::pi);
  facing_ = {std::cos(pose_.heading_rad), std::sin(pose_.heading_rad)};
  if (geometry.clearance(next, radius_m_) < radius_m_) return false;
  for (const PlacedBody& b : others) {
    const double keep = radius_m_ + b.radius_m;
    const double ex = next.x - b.centre.x, ey = next.y - b.centre.y;
    if (ex * ex + ey * ey < keep * keep) return false;
  }
  pose_.x_m = next.x;
  pose_.y_m = next.y;
  return true;
}

}  // namespace esc::sim
