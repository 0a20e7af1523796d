#pragma once
// A robot's IR proximity sensors (at most kMaxIrSensors): layout, ray fan and response
// curve, the Khepera's by default (docs/robot-model.md, "IR sensors").
#include <array>
#include <vector>

#include "runtime/core/rng.hpp"
#include "runtime/sim/arena.hpp"
#include "runtime/sim/geometry2d.hpp"
#include "runtime/sim/neighbours.hpp"
#include "runtime/sim/robot_params.hpp"

namespace esc::sim {

// Enki's IR curve F(x) = m (c - x0^2) / (x^2 - 2 x0 x + c), x in cm, with the Khepera's m
// (the normalised response does not depend on it).
inline constexpr double kEnkiIrM = 1200.0;

[[nodiscard]] double enki_ir_curve(double distance_m, double x0_cm, double c_cm2) noexcept;

// Where sensor `m` sits in the body frame (x along the heading): on the rim of a body of
// `body_radius_m` unless the mount gives its own distance. The light sensors sit there too.
[[nodiscard]] Vec2 mount_point(const IrMount& m, double body_radius_m) noexcept;

// The sensors' normalised response to an obstacle at a distance, clamped to [0, 1]: from a
// measured table (IrParams), or Enki's curve rescaled to 0 at the range and 1 at its peak,
// x0 (Enki holds F = m below x0), or at 0 when x0 is negative (the Khepera's).
class IrResponse {
 public:
  explicit IrResponse(const IrParams& ir);
  [[nodiscard]] double operator()(double distance_m) const noexcept;

 private:
  double range_m_;
  double x0_cm_, c_cm2_;
  double peak_m_;               // max(x0, 0)
  double curve_at_range_;
  double curve_scale_;          // 1 / (F(peak) - F(range))
  std::vector<IrResponsePoint> table_;
};

class IrModel {
 public:
  // `geometry` is the arena's and must outlive the model.
  IrModel(const RobotParams& robot, const StaticGeometry2D& geometry);

  // Normalised response to an obstacle at `distance_m` along a ray (IrResponse).
  [[nodiscard]] double response(double distance_m) const noexcept { return response_(distance_m); }

  // Readings of the robot's sensors at `pose` into out[0 .. sensors()), 0 in the slots
  // after them (noise from `rng` only when noise_sd > 0, one draw per sensor).
  // Uses scratch owned by the model: one reader at a time. Only the walls and obstacles
  // within reach are tested, and each sensor's fan only against those within range of its
  // mount point; a robot with nothing in reach reads 0 without casting a ray. `others`: the
  // bodies of the other robots of a group that may be within reach, which the rays meet too.
  void read(const Pose& pose, std::array<double, 8>& out, Rng& rng,
            std::span<const PlacedBody> others = {}) const noexcept;

  [[nodiscard]] int rays_per_sensor() const noexcept { return rays_; }
  [[nodiscard]] int sensors() const noexcept { return sensors_; }

 private:
  double body_radius_m_;
  double range_m_;
  double noise_sd_;
  int rays_;
  int sensors_;
  IrResponse response_;
  const StaticGeometry2D& geometry_;
  std::vector<double> mount_x_, mount_y_, dir_x_, dir_y_;  // body frame, per ray
  mutable StaticGeometry2D::Nearby near_;                  // scratch: what the robot may see
};

}  // namespace esc::sim
