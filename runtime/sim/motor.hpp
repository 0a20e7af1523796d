#pragma once
// One wheel's motor: the measured speed follows the commanded speed through a first-order
// lag (time constant tau) and an acceleration limit, integrated exactly over one physics
// substep of dt:
//   target = clamp(command, -1, 1) * max_speed
//   lagged = target + (speed - target) * exp(-dt / tau)
//   speed += clamp(lagged - speed, -max_accel * dt, +max_accel * dt)
// With inertia off the speed is the target at once. Motor noise, when the robot has it, is
// an error of the target: target * (1 + noise_sd * N(0, 1)), clamped to the top speed, one
// draw per wheel and control step (docs/robot-model.md).
#include <algorithm>
#include <cmath>

#include "runtime/core/rng.hpp"
#include "runtime/sim/robot_params.hpp"

namespace esc::sim {

class WheelMotor {
 public:
  WheelMotor(const MotorParams& p, double substep_s) noexcept
      : inertia_(p.inertia),
        max_speed_mps_(p.max_speed_mps),
        decay_(p.time_constant_s > 0.0 ? std::exp(-substep_s / p.time_constant_s) : 0.0),
        max_delta_mps_(p.max_accel_mps2 * substep_s),
        noise_sd_(p.noise_sd) {}

  // Commanded wheel speed in m/s; a NaN command counts as 0.
  [[nodiscard]] double target(double command) const noexcept {
    if (std::isnan(command)) return 0.0;
    return std::clamp(command, -1.0, 1.0) * max_speed_mps_;
  }

  [[nodiscard]] bool has_noise() const noexcept { return noise_sd_ > 0.0; }

  // The target a wheel actually pursues over one control step: `target_mps` with its speed
  // error, drawn from `rng` only when the motor is noisy (`rng` may be null otherwise).
  [[nodiscard]] double noisy(double target_mps, Rng* rng) const noexcept {
    if (!has_noise()) return target_mps;
    return std::clamp(target_mps * (1.0 + noise_sd_ * rng->normal()), -max_speed_mps_, max_speed_mps_);
  }

  // Measured speed after one substep, from the measured speed before it.
  [[nodiscard]] double step(double speed_mps, double target_mps) const noexcept {
    if (!inertia_) return target_mps;
    const double lagged = target_mps + (speed_mps - target_mps) * decay_;
    return speed_mps + std::clamp(lagged - speed_mps, -max_delta_mps_, max_delta_mps_);
  }

 private:
  bool inertia_;
  double max_speed_mps_;
  double decay_;          // exp(-dt / tau), 0 when tau = 0
  double max_delta_mps_;  // max_accel * dt
  double noise_sd_;       // speed error, a fraction of the target
};

}  // namespace esc::sim
