#include "runtime/sim/validate.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

namespace esc::sim {

namespace {

[[noreturn]] void fail(const std::string& field, const char* what, double value) {
  std::ostringstream msg;
  msg << field << " must be " << what << " (got " << value << ")";
  throw std::invalid_argument(msg.str());
}

void positive(const std::string& field, double v) {
  if (!(v > 0.0) || !std::isfinite(v)) fail(field, "positive and finite", v);
}
void non_negative(const std::string& field, double v) {
  if (!(v >= 0.0) || !std::isfinite(v)) fail(field, "non-negative and finite", v);
}
void finite(const std::string& field, double v) {
  if (!std::isfinite(v)) fail(field, "finite", v);
}

void inside_arena(const std::string& field, const ArenaSpec& arena, double lo_x, double hi_x,
                  double lo_y, double hi_y) {
  if (lo_x < 0.0 || hi_x > arena.width_m || lo_y < 0.0 || hi_y > arena.height_m) {
    std::ostringstream msg;
    msg << field << " must lie inside the arena [0, " << arena.width_m << "] x [0, "
        << arena.height_m << "] m (it spans [" << lo_x << ", " << hi_x << "] x [" << lo_y
        << ", " << hi_y << "] m)";
    throw std::invalid_argument(msg.str());
  }
}

void validate_zones(const ArenaSpec& arena) {
  if (arena.zones.size() > kMaxZones)
    fail("arena zone count", "at most 8", static_cast<double>(arena.zones.size()));
  for (std::size_t i = 0; i < arena.zones.size(); ++i) {
    const Zone& z = arena.zones[i];
    const std::string f = "arena.zones[" + std::to_string(i) + "]";
    double hx = 0.0;
    double hy = 0.0;
    if (z.shape == ZoneShape::Circle) {
      positive(f + ".radius_m", z.radius_m);
      hx = hy = z.radius_m;
    } else if (z.shape == ZoneShape::Rectangle) {
      positive(f + ".size_m.x", z.size_m.x);
      positive(f + ".size_m.y", z.size_m.y);
      hx = 0.5 * z.size_m.x;
      hy = 0.5 * z.size_m.y;
    } else {
      fail(f + ".shape", "Circle or Rectangle", static_cast<double>(z.shape));
    }
    if (z.random_position) {
      // Only the size matters: the zone must fit.
      inside_arena(f, arena, 0.0, 2 * hx, 0.0, 2 * hy);
    } else {
      finite(f + ".center_m.x", z.center_m.x);
      finite(f + ".center_m.y", z.center_m.y);
      inside_arena(f, arena, z.center_m.x - hx, z.center_m.x + hx, z.center_m.y - hy,
                   z.center_m.y + hy);
    }
  }
}

void validate_lights(const ArenaSpec& arena) {
  if (arena.lights.size() > kMaxLights)
    fail("arena light count", "at most 4", static_cast<double>(arena.lights.size()));
  for (std::size_t i = 0; i < arena.lights.size(); ++i) {
    const LightSource& l = arena.lights[i];
    const std::string f = "arena.lights[" + std::to_string(i) + "]";
    non_negative(f + ".height_m", l.height_m);
    non_negative(f + ".intensity", l.intensity);
    if (l.above_zone < -1 || l.above_zone >= static_cast<int>(arena.zones.size())) {
      std::ostringstream msg;
      msg << f << ".above_zone must be -1 (a fixed light) or the index of a zone, 0.."
          << static_cast<int>(arena.zones.size()) - 1 << " (got " << l.above_zone << ")";
      throw std::invalid_argument(msg.str());
    }
    if (l.above_zone == -1) {
      finite(f + ".position_m.x", l.position_m.x);
      finite(f + ".position_m.y", l.position_m.y);
      inside_arena(f + ".position_m", arena, l.position_m.x, l.position_m.x, l.position_m.y,
                   l.position_m.y);
    }
  }
}

}  // namespace

void validate_arena(const ArenaSpec& arena) {
  positive("arena.width_m", arena.width_m);
  positive("arena.height_m", arena.height_m);
  // Bullet's sweep-and-prune broadphase indexes objects with 16-bit handles.
  constexpr std::size_t kMaxObstacles = 30000;
  if (arena.boxes.size() + arena.cylinders.size() > kMaxObstacles)
    fail("arena obstacle count", "at most 30000", static_cast<double>(arena.boxes.size() + arena.cylinders.size()));
  for (std::size_t i = 0; i < arena.boxes.size(); ++i) {
    const BoxObstacle& b = arena.boxes[i];
    const std::string f = "arena.boxes[" + std::to_string(i) + "]";
    finite(f + ".center_m.x", b.center_m.x);
    finite(f + ".center_m.y", b.center_m.y);
    positive(f + ".size_m.x", b.size_m.x);
    positive(f + ".size_m.y", b.size_m.y);
    finite(f + ".angle_rad", b.angle_rad);
  }
  for (std::size_t i = 0; i < arena.cylinders.size(); ++i) {
    const CylinderObstacle& c = arena.cylinders[i];
    const std::string f = "arena.cylinders[" + std::to_string(i) + "]";
    finite(f + ".center_m.x", c.center_m.x);
    finite(f + ".center_m.y", c.center_m.y);
    positive(f + ".radius_m", c.radius_m);
  }
  if (arena.fixed_start) {
    finite("arena.fixed_start.x_m", arena.fixed_start->x_m);
    finite("arena.fixed_start.y_m", arena.fixed_start->y_m);
    finite("arena.fixed_start.heading_rad", arena.fixed_start->heading_rad);
  }
  validate_zones(arena);
  validate_lights(arena);
  positive("arena.sweep_cell_m", arena.sweep_cell_m);
  const double cells = std::ceil(arena.width_m / arena.sweep_cell_m) *
                       std::ceil(arena.height_m / arena.sweep_cell_m);
  if (cells > kMaxSweepCells) {
    std::ostringstream msg;
    msg << "arena.sweep_cell_m must be larger: " << arena.sweep_cell_m << " m cells make "
        << cells << " cells, more than " << kMaxSweepCells;
    throw std::invalid_argument(msg.str());
  }
  positive("arena.reach_radius_m", arena.reach_radius_m);
}

void validate_robot(const KheperaParams& robot) {
  positive("robot.body_radius_m", robot.body_radius_m);
  positive("robot.body_height_m", robot.body_height_m);
  positive("robot.mass_kg", robot.mass_kg);
  positive("robot.wheel_base_m", robot.wheel_base_m);
  positive("robot.motor.max_speed_mps", robot.motor.max_speed_mps);
  non_negative("robot.motor.time_constant_s", robot.motor.time_constant_s);
  positive("robot.motor.max_accel_mps2", robot.motor.max_accel_mps2);
  positive("robot.ir.range_m", robot.ir.range_m);
  if (!(robot.ir.aperture_rad >= 0.0) || !(robot.ir.aperture_rad < std::numbers::pi))
    fail("robot.ir.aperture_rad", "in [0, pi)", robot.ir.aperture_rad);
  if (robot.ir.rays < 1 || robot.ir.rays > 64)
    fail("robot.ir.rays", "between 1 and 64", robot.ir.rays);
  non_negative("robot.ir.noise_sd", robot.ir.noise_sd);
  positive("robot.control_step_s", robot.control_step_s);
  if (robot.physics_substeps < 1 || robot.physics_substeps > 1000)
    fail("robot.physics_substeps", "between 1 and 1000", robot.physics_substeps);
  positive("robot.light.half_distance_m", robot.light.half_distance_m);
  non_negative("robot.light.noise_sd", robot.light.noise_sd);
  if (robot.energy.discharge_steps < 1 || robot.energy.discharge_steps > kMaxEnergySteps)
    fail("robot.energy.discharge_steps", "between 1 and 10000000", robot.energy.discharge_steps);
  if (robot.energy.recharge_steps < 1 || robot.energy.recharge_steps > kMaxEnergySteps)
    fail("robot.energy.recharge_steps", "between 1 and 10000000", robot.energy.recharge_steps);
  // Fastest point of the body: centre speed plus rim speed, at most
  // max_speed * max(1, 2 R / wheel_base) for commands in [-1, 1].
  const double dt_sub = robot.control_step_s / robot.physics_substeps;
  const double travel = robot.motor.max_speed_mps *
                        std::max(1.0, 2.0 * robot.body_radius_m / robot.wheel_base_m) * dt_sub;
  if (travel > kMaxTravelPerSubstep_m) {
    std::ostringstream msg;
    msg << "robot.physics_substeps must be larger: the body moves up to " << travel
        << " m per substep, more than the " << kMaxTravelPerSubstep_m
        << " m the contact solver looks ahead (raise physics_substeps, or lower "
           "motor.max_speed_mps or control_step_s)";
    throw std::invalid_argument(msg.str());
  }
}

}  // namespace esc::sim
