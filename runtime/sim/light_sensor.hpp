#pragma once
// The ambient-light sensors: the IR sensors (the Khepera's TCRT1000) in passive mode, at the
// IR mounts and facing the IR directions (robot_params.hpp). Model and constants in
// docs/robot-model.md, "Ambient light".
#include <array>
#include <cstddef>

#include "runtime/core/rng.hpp"
#include "runtime/sim/arena.hpp"
#include "runtime/sim/geometry2d.hpp"
#include "runtime/sim/robot_params.hpp"

namespace esc::sim {

inline constexpr int kLightSensors = kMaxIrSensors;

// A light where it stands this epoch (its zone may have been placed at random).
struct PlacedLight {
  double x_m = 0.0;        // floor position
  double y_m = 0.0;
  double height_m = 0.0;   // above the sensors' plane
  double intensity = 1.0;
};

// Two points closer than this along a sensor-to-light segment count as the same point:
// a hit at least this much before the light occludes it.
inline constexpr double kLightOcclusionTolerance_m = 1e-9;

class LightModel {
 public:
  explicit LightModel(const RobotParams& robot);

  // Unoccluded contribution of a light of `intensity` at straight-line distance `distance_m`
  // (3D: floor offset and height) whose direction makes cos_incidence with the facing.
  [[nodiscard]] double response(double intensity, double distance_m,
                                double cos_incidence) const noexcept;

  // Readings of the robot at `pose` from `n` lights, 0 dark .. 1 bright, one per IR mount, 0
  // in the slots after them (noise from `rng` only when noise_sd > 0: one draw per sensor,
  // in index order). No allocation.
  void read(const Pose& pose, const StaticGeometry2D& geometry, const PlacedLight* lights,
            std::size_t n, std::array<double, kLightSensors>& out, Rng& rng) const noexcept;

 private:
  double body_radius_m_;
  double inv_half_distance2_;   // 1 / half_distance^2
  double noise_sd_;
  std::size_t sensors_;
  std::array<double, kLightSensors> mount_x_{}, mount_y_{}, face_x_{}, face_y_{};  // body frame
};

}  // namespace esc::sim
