#include "compiler/robot_settings.hpp"

#include <limits>
#include <utility>

#include <fmt/format.h>

#include "compiler/quantities.hpp"
#include "compiler/setting_values.hpp"
#include "compiler/table_lookup.hpp"

namespace esc::compiler {

namespace {

using K = RobotSetting::Kind;

}  // namespace

const std::vector<RobotSetting>& robot_settings() {
  static const std::vector<RobotSetting> table = {
      {"inertia", K::Flag, Dim::None, "motor inertia on or off",
       [](const sim::KheperaParams& p) { return p.motor.inertia ? 1.0 : 0.0; },
       [](sim::KheperaParams& p, double v) { p.motor.inertia = v != 0.0; }},
      {"max_speed", K::Quantity, Dim::Speed, "wheel speed of command 1.0",
       [](const sim::KheperaParams& p) { return p.motor.max_speed_mps; },
       [](sim::KheperaParams& p, double v) { p.motor.max_speed_mps = v; }},
      {"time_constant", K::Quantity, Dim::Time, "first-order lag of the wheels",
       [](const sim::KheperaParams& p) { return p.motor.time_constant_s; },
       [](sim::KheperaParams& p, double v) { p.motor.time_constant_s = v; }},
      {"max_accel", K::Quantity, Dim::Accel, "acceleration limit of each wheel",
       [](const sim::KheperaParams& p) { return p.motor.max_accel_mps2; },
       [](sim::KheperaParams& p, double v) { p.motor.max_accel_mps2 = v; }},
      {"body_radius", K::Quantity, Dim::Length, "radius of the cylindrical body",
       [](const sim::KheperaParams& p) { return p.body_radius_m; },
       [](sim::KheperaParams& p, double v) { p.body_radius_m = v; }},
      {"body_height", K::Quantity, Dim::Length, "height of the body",
       [](const sim::KheperaParams& p) { return p.body_height_m; },
       [](sim::KheperaParams& p, double v) { p.body_height_m = v; }},
      {"wheel_base", K::Quantity, Dim::Length, "distance between the wheels",
       [](const sim::KheperaParams& p) { return p.wheel_base_m; },
       [](sim::KheperaParams& p, double v) { p.wheel_base_m = v; }},
      {"mass", K::Quantity, Dim::Mass, "mass of the robot",
       [](const sim::KheperaParams& p) { return p.mass_kg; },
       [](sim::KheperaParams& p, double v) { p.mass_kg = v; }},
      {"control_step", K::Quantity, Dim::Time, "duration of one control step",
       [](const sim::KheperaParams& p) { return p.control_step_s; },
       [](sim::KheperaParams& p, double v) { p.control_step_s = v; }},
      {"substeps", K::Whole, Dim::None, "physics steps per control step",
       [](const sim::KheperaParams& p) { return static_cast<double>(p.physics_substeps); },
       [](sim::KheperaParams& p, double v) { p.physics_substeps = static_cast<int>(v); }},
      {"motor_noise", K::Quantity, Dim::None, "standard deviation of each wheel's speed error (fraction of its command)",
       [](const sim::KheperaParams& p) { return p.motor.noise_sd; },
       [](sim::KheperaParams& p, double v) { p.motor.noise_sd = v; }},
      {"ir_range", K::Quantity, Dim::Length, "IR reading is 0 at and beyond this distance",
       [](const sim::KheperaParams& p) { return p.ir.range_m; },
       [](sim::KheperaParams& p, double v) { p.ir.range_m = v; }},
      {"ir_aperture", K::Quantity, Dim::Angle, "angle spanned by a sensor's rays",
       [](const sim::KheperaParams& p) { return p.ir.aperture_rad; },
       [](sim::KheperaParams& p, double v) { p.ir.aperture_rad = v; }},
      {"ir_rays", K::Whole, Dim::None, "rays per IR sensor",
       [](const sim::KheperaParams& p) { return static_cast<double>(p.ir.rays); },
       [](sim::KheperaParams& p, double v) { p.ir.rays = static_cast<int>(v); }},
      {"ir_noise", K::Quantity, Dim::None, "standard deviation of IR noise (readings 0..1)",
       [](const sim::KheperaParams& p) { return p.ir.noise_sd; },
       [](sim::KheperaParams& p, double v) { p.ir.noise_sd = v; }},
      {"light_half_distance", K::Quantity, Dim::Length, "a unit light straight ahead at this distance reads 0.5",
       [](const sim::KheperaParams& p) { return p.light.half_distance_m; },
       [](sim::KheperaParams& p, double v) { p.light.half_distance_m = v; }},
      {"light_noise", K::Quantity, Dim::None, "standard deviation of light noise (readings 0..1)",
       [](const sim::KheperaParams& p) { return p.light.noise_sd; },
       [](sim::KheperaParams& p, double v) { p.light.noise_sd = v; }},
      {"energy", K::Flag, Dim::None, "energy accumulator on or off",
       [](const sim::KheperaParams& p) { return p.energy.enabled ? 1.0 : 0.0; },
       [](sim::KheperaParams& p, double v) { p.energy.enabled = v != 0.0; }},
      {"energy_discharge", K::Whole, Dim::None, "control steps from full to empty",
       [](const sim::KheperaParams& p) { return static_cast<double>(p.energy.discharge_steps); },
       [](sim::KheperaParams& p, double v) { p.energy.discharge_steps = static_cast<int>(v); }},
      {"energy_recharge", K::Whole, Dim::None, "control steps from empty to full in a recharge zone",
       [](const sim::KheperaParams& p) { return static_cast<double>(p.energy.recharge_steps); },
       [](sim::KheperaParams& p, double v) { p.energy.recharge_steps = static_cast<int>(v); }},
      {"rangefinders", K::Angles, Dim::Angle,
       "rangefinders' angles from the heading (positive = left), in the order `range[i]` reads them",
       nullptr, nullptr,
       [](const sim::KheperaParams& p) { return std::span<const double>(p.rangefinders.angles_rad); },
       [](sim::KheperaParams& p, std::vector<double> v) { p.rangefinders.angles_rad = std::move(v); }},
      {"rangefinder_range", K::Quantity, Dim::Length, "rangefinders read 1 at and beyond this distance",
       [](const sim::KheperaParams& p) { return p.rangefinders.range_m; },
       [](sim::KheperaParams& p, double v) { p.rangefinders.range_m = v; }},
      {"radars", K::Whole, Dim::None, "pie-slice goal radars around the body (0: none)",
       [](const sim::KheperaParams& p) { return static_cast<double>(p.radars); },
       [](sim::KheperaParams& p, double v) { p.radars = static_cast<int>(v); }},
  };
  return table;
}

const RobotSetting* find_robot_setting(std::string_view name) {
  return find_row(robot_settings(), &RobotSetting::name, name);
}

std::vector<std::string> robot_setting_names() { return row_names(robot_settings(), &RobotSetting::name); }

namespace {

// One number: SI, a flag 0 or 1.
std::optional<double> read_number(const RobotSetting& s, const ast::Value& v, Sink& sink) {
  switch (s.kind) {
    case K::Flag:
      if (const auto f = read_flag(v, s.name, sink)) return *f ? 1.0 : 0.0;
      return std::nullopt;
    case K::Whole: {
      // Syntax only (a count that fits the field); the range is the runtime's rule.
      constexpr long long kIntMax = std::numeric_limits<int>::max();
      if (const auto n = read_count(v, s.name, -kIntMax, kIntMax, sink)) return static_cast<double>(*n);
      return std::nullopt;
    }
    case K::Quantity: return read_quantity(v, s.name, s.dim, sink);
    case K::Angles: break;
  }
  return std::nullopt;
}

}  // namespace

bool apply_robot_value(const RobotSetting& s, const ast::Value& v, sim::KheperaParams& p, Sink& sink) {
  if (s.kind != K::Angles) {
    const auto n = read_number(s, v, sink);
    if (n) s.set(p, *n);
    return n.has_value();
  }
  const auto angles = read_list(v, s.name, s.dim, "[90deg, 0deg, -90deg]", sink);
  if (angles) s.set_angles(p, std::move(*angles));
  return angles.has_value();
}

std::string robot_value_text(const RobotSetting& s, const sim::KheperaParams& p) {
  if (s.kind == K::Angles) {
    std::vector<std::string> items;
    for (const double a : s.get_angles(p)) items.push_back(number_text(a) + " rad");
    return fmt::format("[{}]", fmt::join(items, ", "));
  }
  const double v = s.get(p);
  if (s.kind == K::Flag) return v != 0.0 ? "on" : "off";
  if (s.kind == K::Whole) return fmt::format("{}", static_cast<long long>(v));
  const std::string_view u = si_unit(s.dim);
  return u.empty() ? number_text(v) : fmt::format("{} {}", number_text(v), u);
}

}  // namespace esc::compiler
