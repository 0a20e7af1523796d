#pragma once
// The Khepera's eight IR proximity sensors: layout, ray fan and response curve
// (docs/robot-model.md). Index 0..5: front, left to right; 6: back left; 7: back right.
#include <array>
#include <vector>

#include "runtime/core/rng.hpp"
#include "runtime/sim/arena.hpp"
#include "runtime/sim/geometry2d.hpp"
#include "runtime/sim/khepera_params.hpp"

namespace esc::sim {

// Mount angle on the body perimeter and facing direction, degrees from the heading,
// positive = left (counter-clockwise).
inline constexpr std::array<double, 8> kIrMountDeg = {68.0, 43.0, 13.0, -13.0,
                                                      -43.0, -68.0, 158.0, -158.0};
inline constexpr std::array<double, 8> kIrFacingDeg = {90.0, 45.0, 10.0, -10.0,
                                                       -45.0, -90.0, 180.0, 180.0};

// Enki's Khepera IR curve F(x) = m (c - x0^2) / (x^2 - 2 x0 x + c), x in cm.
inline constexpr double kEnkiIrM = 1200.0;
inline constexpr double kEnkiIrX0_cm = -0.9;
inline constexpr double kEnkiIrC_cm2 = 7.0;

[[nodiscard]] double enki_ir_curve(double distance_m) noexcept;

class IrModel {
 public:
  // `geometry` is the arena's and must outlive the model.
  IrModel(const KheperaParams& robot, const StaticGeometry2D& geometry);

  // Normalised response to an obstacle at `distance_m` along a ray: 1 at 0, falling with
  // Enki's curve, shifted and rescaled to reach 0 at range; clamped to [0, 1].
  [[nodiscard]] double response(double distance_m) const noexcept;

  // Readings of the robot at `pose` (noise from `rng` only when noise_sd > 0).
  // Uses scratch owned by the model: one reader at a time. Only the walls and obstacles
  // within reach are tested, and each sensor's fan only against those within range of its
  // mount point; a robot with nothing in reach reads 0 without casting a ray.
  void read(const Pose& pose, std::array<double, 8>& out, Rng& rng) const noexcept;

  [[nodiscard]] int rays_per_sensor() const noexcept { return rays_; }

 private:
  double body_radius_m_;
  double range_m_;
  double noise_sd_;
  int rays_;
  double curve_at_range_;
  double curve_scale_;          // 1 / (F(0) - F(range))
  const StaticGeometry2D& geometry_;
  std::vector<double> mount_x_, mount_y_, dir_x_, dir_y_;  // body frame, per ray
  mutable StaticGeometry2D::Nearby near_;                  // scratch: what the robot may see
};

}  // namespace esc::sim
