#pragma once
// The Khepera's differential drive: measured wheel speeds (after the motors, motor.hpp) to
// the planar velocity World imposes on the body for one physics substep of dt. Plain C++,
// no Bullet, so that a reader finds the kinematics in one short file.
//
// With wheel speeds v_l, v_r and wheel base L, wheels that do not slip move the centre at
//   v = (v_l + v_r) / 2            along the heading h, and turn the body at
//   w = (v_r - v_l) / L.
// Over the substep the centre follows the arc of (v, w) exactly. The chord from its start to
// its end has length v dt sin(w dt / 2) / (w dt / 2) and points along h turned by w dt / 2:
//   chord = v sin(a) / a   (chord = v when a = 0),   a = w dt / 2
//   u     = chord * (cos a h_x - sin a h_y,  sin a h_x + cos a h_y)
// Moving at velocity u while turning at w for dt (Bullet integrates the rotation by the
// exponential map, exactly) puts the body at the arc's end with the arc's heading.
#include <cmath>

#include "runtime/sim/arena.hpp"

namespace esc::sim {

// What the body is given for one substep.
struct PlanarVelocity {
  double x_mps = 0.0;        // u: velocity of the centre, world frame
  double y_mps = 0.0;
  double turn_radps = 0.0;   // w, counter-clockwise
  double travel_m = 0.0;     // |chord| dt: how far the centre moves in the substep
  // cos and sin of the half turn w dt / 2, which the body's rotation over the substep needs
  // too (Body::integrate): computed once.
  double cos_half_turn = 1.0;
  double sin_half_turn = 0.0;
};

class DifferentialDrive {
 public:
  DifferentialDrive(double wheel_base_m, double substep_s) noexcept
      : inv_wheel_base_per_m_(1.0 / wheel_base_m), substep_s_(substep_s) {}

  // `heading` is the body's unit heading vector at the start of the substep.
  [[nodiscard]] PlanarVelocity velocity(double left_mps, double right_mps, Vec2 heading) const noexcept {
    const double v_mps = 0.5 * (left_mps + right_mps);
    const double turn_radps = (right_mps - left_mps) * inv_wheel_base_per_m_;
    const double half_turn_rad = 0.5 * turn_radps * substep_s_;
    const double c = std::cos(half_turn_rad);
    const double s = std::sin(half_turn_rad);
    const double chord_mps = half_turn_rad == 0.0 ? v_mps : v_mps * s / half_turn_rad;
    return {chord_mps * (c * heading.x - s * heading.y), chord_mps * (s * heading.x + c * heading.y), turn_radps,
            std::abs(chord_mps) * substep_s_, c, s};
  }

 private:
  double inv_wheel_base_per_m_;
  double substep_s_;
};

}  // namespace esc::sim
