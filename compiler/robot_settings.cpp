#include "compiler/robot_settings.hpp"

#include <array>
#include <limits>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "compiler/quantities.hpp"
#include "compiler/setting_values.hpp"
#include "compiler/table_lookup.hpp"
#include "runtime/expr/observables.hpp"

namespace esc::compiler {

namespace {

using K = RobotSetting::Kind;

// Enki's IR curve is held in its own units (robot_params.hpp). A value written in them
// (`-0.9cm`) comes back through SI one rounding off (-0.9000000000000001): rounded to 12
// significant digits it is the number written, so a script restating the Khepera's curve
// simulates exactly the default one.
constexpr double kCmPerM = 100.0;
constexpr double kCm2PerM2 = 1e4;
double in_enki_units(double si, double scale) { return std::stod(fmt::format("{:.12g}", si * scale)); }

std::string with_unit(double v, Dim d) { return fmt::format("{} {}", number_text(v), si_unit(d)); }

// A list setting's value as resolved settings show it: `[A, B, ...]`, each item's text.
template <class Items, class Text>
std::string bracketed(const Items& items, Text text) {
  std::vector<std::string> shown;
  for (const auto& item : items) shown.push_back(text(item));
  return fmt::format("[{}]", fmt::join(shown, ", "));
}

// A list of tuples into `out`, each item made by `make` from its numbers (SI).
template <class Item, class Make>
bool read_rows(const ast::Value& v, std::string_view name, const TupleShape& shape, std::vector<Item>& out, Make make,
               Sink& sink) {
  const auto rows = read_tuples(v, name, shape, sink);
  if (!rows) return false;
  out.clear();
  for (const std::vector<double>& r : *rows) out.push_back(make(r));
  return true;
}

// The two numbers of a pair, as an aggregate of two doubles.
template <class Item>
Item pair_of(const std::vector<double>& r) {
  return {r[0], r[1]};
}

bool read_rangefinders(const ast::Value& v, std::string_view name, sim::RobotParams& p, Sink& sink) {
  auto angles = read_list(v, name, Dim::Angle, "[90deg, 0deg, -90deg]", sink);
  if (angles) p.rangefinders.angles_rad = std::move(*angles);
  return angles.has_value();
}

std::string rangefinders_text(const sim::RobotParams& p) {
  return bracketed(p.rangefinders.angles_rad, [](double a) { return with_unit(a, Dim::Angle); });
}

constexpr Dim kMountDims[] = {Dim::Angle, Dim::Angle, Dim::Length};

bool read_ir_sensors(const ast::Value& v, std::string_view name, sim::RobotParams& p, Sink& sink) {
  return read_rows(v, name, {kMountDims, 1, "[(68deg, 90deg), (43deg, 45deg, 27mm)]"}, p.ir.mounts,
                   [](const std::vector<double>& r) {
                     return sim::IrMount{r[0], r[1], r.size() > 2 ? std::optional<double>(r[2]) : std::nullopt};
                   },
                   sink);
}

std::string ir_sensors_text(const sim::RobotParams& p) {
  return bracketed(p.ir.mounts, [](const sim::IrMount& m) {
    return fmt::format("({}, {}{})", with_unit(m.bearing_rad, Dim::Angle), with_unit(m.facing_rad, Dim::Angle),
                       m.radius_m ? ", " + with_unit(*m.radius_m, Dim::Length) : "");
  });
}

constexpr Dim kPointDims[] = {Dim::Length, Dim::Length};

bool read_body_outline(const ast::Value& v, std::string_view name, sim::RobotParams& p, Sink& sink) {
  return read_rows(v, name, {kPointDims, 0, "[(8cm, 0cm), (0cm, 5.5cm), (-3cm, 0cm), (0cm, -5.5cm)]"}, p.outline,
                   pair_of<sim::Vec2>, sink);
}

std::string body_outline_text(const sim::RobotParams& p) {
  return bracketed(p.outline, [](const sim::Vec2& v) {
    return fmt::format("({}, {})", with_unit(v.x, Dim::Length), with_unit(v.y, Dim::Length));
  });
}

constexpr std::array<std::pair<std::string_view, sim::DriveKind>, 2> kDrives{
    {{"differential", sim::DriveKind::Differential}, {"acceleration", sim::DriveKind::Acceleration}}};

bool read_drive(const ast::Value& v, std::string_view name, sim::RobotParams& p, Sink& sink) {
  std::vector<std::string> words;
  for (const auto& [word, kind] : kDrives) words.emplace_back(word);
  const auto i = read_word(v, name, words, sink);
  if (i) p.drive = kDrives[*i].second;
  return i.has_value();
}

std::string drive_text(const sim::RobotParams& p) {
  for (const auto& [word, kind] : kDrives)
    if (kind == p.drive) return std::string(word);
  return "";
}

// A name for the sensor array `observable` reads: itself, or a name no observable has (a
// robot's sensors never hide another reading).
bool read_sensor_name(const ast::Value& v, std::string_view name, std::string_view observable,
                      std::string_view example, std::string& out, Sink& sink) {
  if (v.kind != ast::Value::Kind::Word) {
    sink.error(v.where, fmt::format("`{}` takes a name, as in `{} {}`, found `{}`", name, name, example, v.text));
    return false;
  }
  if (v.text != observable && expr::find_observable(v.text)) {
    sink.error(v.where, fmt::format("`{}` is an observable of every robot; these sensors need a name of their own",
                                    v.text))
        .help.push_back(fmt::format("write `{} {}`", name, example));
    return false;
  }
  out = v.text;
  return true;
}

constexpr Dim kSectorDims[] = {Dim::Angle, Dim::Angle};

bool read_bumpers(const ast::Value& v, std::string_view name, sim::RobotParams& p, Sink& sink) {
  return read_rows(v, name, {kSectorDims, 0, "[(-45deg, 45deg), (135deg, 225deg)]"}, p.bumpers,
                   pair_of<sim::BumperSector>, sink);
}

std::string bumpers_text(const sim::RobotParams& p) {
  return bracketed(p.bumpers, [](const sim::BumperSector& b) {
    return fmt::format("({}, {})", with_unit(b.from_rad, Dim::Angle), with_unit(b.to_rad, Dim::Angle));
  });
}

constexpr Dim kGroundDims[] = {Dim::Angle, Dim::Length};

bool read_ground_sensors(const ast::Value& v, std::string_view name, sim::RobotParams& p, Sink& sink) {
  return read_rows(v, name, {kGroundDims, 0, "[(9deg, 7.3cm), (-9deg, 7.3cm)]"}, p.ground.mounts,
                   pair_of<sim::GroundMount>, sink);
}

std::string ground_sensors_text(const sim::RobotParams& p) {
  return bracketed(p.ground.mounts, [](const sim::GroundMount& m) {
    return fmt::format("({}, {})", with_unit(m.bearing_rad, Dim::Angle), with_unit(m.radius_m, Dim::Length));
  });
}

constexpr Dim kResponseDims[] = {Dim::Length, Dim::None};

bool read_ir_response(const ast::Value& v, std::string_view name, sim::RobotParams& p, Sink& sink) {
  return read_rows(v, name, {kResponseDims, 0, "[(0cm, 1), (2cm, 0.4), (5cm, 0)]"}, p.ir.response,
                   pair_of<sim::IrResponsePoint>, sink);
}

std::string ir_response_text(const sim::RobotParams& p) {
  return bracketed(p.ir.response, [](const sim::IrResponsePoint& r) {
    return fmt::format("({}, {})", with_unit(r.distance_m, Dim::Length), number_text(r.reading));
  });
}

}  // namespace

const std::vector<RobotSetting>& robot_settings() {
  static const std::vector<RobotSetting> table = {
      {"drive", K::Word, Dim::None,
       "`differential` (two wheels behind motors) or `acceleration` (Lehman & Stanley's navigator: the commands "
       "accelerate the turn rate and the speed, the body kinematic)",
       nullptr, nullptr, read_drive, drive_text},
      {"max_turn_rate", K::Quantity, Dim::TurnRate, "the acceleration drive's top turn rate",
       [](const sim::RobotParams& p) { return p.turn.max_rate_radps; },
       [](sim::RobotParams& p, double v) { p.turn.max_rate_radps = v; }},
      {"max_turn_accel", K::Quantity, Dim::TurnAccel, "the acceleration drive's change of turn rate at command 1",
       [](const sim::RobotParams& p) { return p.turn.max_accel_radps2; },
       [](sim::RobotParams& p, double v) { p.turn.max_accel_radps2 = v; }},
      {"inertia", K::Flag, Dim::None, "motor inertia on or off",
       [](const sim::RobotParams& p) { return p.motor.inertia ? 1.0 : 0.0; },
       [](sim::RobotParams& p, double v) { p.motor.inertia = v != 0.0; }},
      {"max_speed", K::Quantity, Dim::Speed, "wheel speed of command 1.0",
       [](const sim::RobotParams& p) { return p.motor.max_speed_mps; },
       [](sim::RobotParams& p, double v) { p.motor.max_speed_mps = v; }},
      {"time_constant", K::Quantity, Dim::Time, "first-order lag of the wheels",
       [](const sim::RobotParams& p) { return p.motor.time_constant_s; },
       [](sim::RobotParams& p, double v) { p.motor.time_constant_s = v; }},
      {"max_accel", K::Quantity, Dim::Accel, "acceleration limit of each wheel",
       [](const sim::RobotParams& p) { return p.motor.max_accel_mps2; },
       [](sim::RobotParams& p, double v) { p.motor.max_accel_mps2 = v; }},
      {"body_radius", K::Quantity, Dim::Length, "radius of the cylindrical body (with an outline: the circle around it)",
       [](const sim::RobotParams& p) { return p.body_radius_m; },
       [](sim::RobotParams& p, double v) { p.body_radius_m = v; }},
      {"body_outline", K::List, Dim::Length,
       "a convex outline instead of the disc: its vertices (x ahead, y to the left of the point the wheels turn "
       "about), in order round it",
       nullptr, nullptr, read_body_outline, body_outline_text},
      {"body_height", K::Quantity, Dim::Length, "height of the body",
       [](const sim::RobotParams& p) { return p.body_height_m; },
       [](sim::RobotParams& p, double v) { p.body_height_m = v; }},
      {"wheel_base", K::Quantity, Dim::Length, "distance between the wheels",
       [](const sim::RobotParams& p) { return p.wheel_base_m; },
       [](sim::RobotParams& p, double v) { p.wheel_base_m = v; }},
      {"mass", K::Quantity, Dim::Mass, "mass of the robot",
       [](const sim::RobotParams& p) { return p.mass_kg; },
       [](sim::RobotParams& p, double v) { p.mass_kg = v; }},
      {"control_step", K::Quantity, Dim::Time, "duration of one control step",
       [](const sim::RobotParams& p) { return p.control_step_s; },
       [](sim::RobotParams& p, double v) { p.control_step_s = v; }},
      {"substeps", K::Whole, Dim::None, "physics steps per control step",
       [](const sim::RobotParams& p) { return static_cast<double>(p.physics_substeps); },
       [](sim::RobotParams& p, double v) { p.physics_substeps = static_cast<int>(v); }},
      {"motor_noise", K::Quantity, Dim::None, "standard deviation of each wheel's speed error (fraction of its command)",
       [](const sim::RobotParams& p) { return p.motor.noise_sd; },
       [](sim::RobotParams& p, double v) { p.motor.noise_sd = v; }},
      {"ir_range", K::Quantity, Dim::Length, "IR reading is 0 at and beyond this distance",
       [](const sim::RobotParams& p) { return p.ir.range_m; },
       [](sim::RobotParams& p, double v) { p.ir.range_m = v; }},
      {"ir_aperture", K::Quantity, Dim::Angle, "angle spanned by a sensor's rays",
       [](const sim::RobotParams& p) { return p.ir.aperture_rad; },
       [](sim::RobotParams& p, double v) { p.ir.aperture_rad = v; }},
      {"ir_rays", K::Whole, Dim::None, "rays per IR sensor",
       [](const sim::RobotParams& p) { return static_cast<double>(p.ir.rays); },
       [](sim::RobotParams& p, double v) { p.ir.rays = static_cast<int>(v); }},
      {"ir_noise", K::Quantity, Dim::None, "standard deviation of IR noise (readings 0..1)",
       [](const sim::RobotParams& p) { return p.ir.noise_sd; },
       [](sim::RobotParams& p, double v) { p.ir.noise_sd = v; }},
      {"ir_sensors", K::List, Dim::Angle,
       "the IR sensors, in the order `ir[i]` reads them: (mount bearing, facing[, distance from the centre]), "
       "angles from the heading",
       nullptr, nullptr, read_ir_sensors, ir_sensors_text},
      {kRenamableSensors[0].setting, K::Word, Dim::None,
       "the name scripts read the IR sensors by (`ir[i]`; the e-puck's `prox[i]`)", nullptr, nullptr,
       [](const ast::Value& v, std::string_view name, sim::RobotParams& p, Sink& sink) {
         return read_sensor_name(v, name, kRenamableSensors[0].observable, "prox", p.ir.name, sink);
       },
       [](const sim::RobotParams& p) { return p.ir.name; }, true},
      {"ir_curve_x0", K::Quantity, Dim::Length, "x0 of Enki's IR curve m (c - x0^2) / (x^2 - 2 x0 x + c)",
       [](const sim::RobotParams& p) { return p.ir.curve_x0_cm / kCmPerM; },
       [](sim::RobotParams& p, double v) { p.ir.curve_x0_cm = in_enki_units(v, kCmPerM); }},
      {"ir_curve_c", K::Quantity, Dim::Area, "c of Enki's IR curve",
       [](const sim::RobotParams& p) { return p.ir.curve_c_cm2 / kCm2PerM2; },
       [](sim::RobotParams& p, double v) { p.ir.curve_c_cm2 = in_enki_units(v, kCm2PerM2); }},
      {"ir_response", K::List, Dim::Length,
       "a measured IR response instead of the curve: (distance, reading) at increasing distances",
       nullptr, nullptr, read_ir_response, ir_response_text},
      {"light_half_distance", K::Quantity, Dim::Length, "a unit light straight ahead at this distance reads 0.5",
       [](const sim::RobotParams& p) { return p.light.half_distance_m; },
       [](sim::RobotParams& p, double v) { p.light.half_distance_m = v; }},
      {"light_noise", K::Quantity, Dim::None, "standard deviation of light noise (readings 0..1)",
       [](const sim::RobotParams& p) { return p.light.noise_sd; },
       [](sim::RobotParams& p, double v) { p.light.noise_sd = v; }},
      {"emission", K::Quantity, Dim::None,
       "light the robot gives off, seen by the other robots' light sensors as an arena light of this intensity; 0: none",
       [](const sim::RobotParams& p) { return p.emission.intensity; },
       [](sim::RobotParams& p, double v) { p.emission.intensity = v; }},
      {"emission_height", K::Quantity, Dim::Length, "height of the robot's light above the sensors' plane",
       [](const sim::RobotParams& p) { return p.emission.height_m; },
       [](sim::RobotParams& p, double v) { p.emission.height_m = v; }},
      {"energy", K::Flag, Dim::None, "energy accumulator on or off",
       [](const sim::RobotParams& p) { return p.energy.enabled ? 1.0 : 0.0; },
       [](sim::RobotParams& p, double v) { p.energy.enabled = v != 0.0; }},
      {"energy_discharge", K::Whole, Dim::None, "control steps from full to empty",
       [](const sim::RobotParams& p) { return static_cast<double>(p.energy.discharge_steps); },
       [](sim::RobotParams& p, double v) { p.energy.discharge_steps = static_cast<int>(v); }},
      {"energy_recharge", K::Whole, Dim::None, "control steps from empty to full in a recharge zone",
       [](const sim::RobotParams& p) { return static_cast<double>(p.energy.recharge_steps); },
       [](sim::RobotParams& p, double v) { p.energy.recharge_steps = static_cast<int>(v); }},
      {"rangefinders", K::List, Dim::Angle,
       "rangefinders' angles from the heading (positive = left), in the order `range[i]` reads them",
       nullptr, nullptr, read_rangefinders, rangefinders_text},
      {"rangefinder_range", K::Quantity, Dim::Length, "rangefinders read 1 at and beyond this distance",
       [](const sim::RobotParams& p) { return p.rangefinders.range_m; },
       [](sim::RobotParams& p, double v) { p.rangefinders.range_m = v; }},
      {"radars", K::Whole, Dim::None, "pie-slice goal radars around the body (0: none)",
       [](const sim::RobotParams& p) { return static_cast<double>(p.radars); },
       [](sim::RobotParams& p, double v) { p.radars = static_cast<int>(v); }},
      {"ground_sensors", K::List, Dim::Angle,
       "ground sensors under the body, in the order `ground_sensor[i]` reads them: (bearing from the heading, "
       "distance from the centre)",
       nullptr, nullptr, read_ground_sensors, ground_sensors_text},
      {"bumpers", K::List, Dim::Angle,
       "bumpers in the order `bumper[i]` reads them: (from, to), the sector of the body's edge counter-clockwise "
       "from one bearing to the other",
       nullptr, nullptr, read_bumpers, bumpers_text},
      {kRenamableSensors[1].setting, K::Word, Dim::None,
       "the name scripts read the ground sensors by (`ground_sensor[i]`; the Thymio's `prox_ground[i]`)", nullptr,
       nullptr,
       [](const ast::Value& v, std::string_view name, sim::RobotParams& p, Sink& sink) {
         return read_sensor_name(v, name, kRenamableSensors[1].observable, "prox_ground", p.ground.name, sink);
       },
       [](const sim::RobotParams& p) { return p.ground.name; }, true},
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
    case K::List:
    case K::Word: break;
  }
  return std::nullopt;
}

}  // namespace

bool apply_robot_value(const RobotSetting& s, const ast::Value& v, sim::RobotParams& p, Sink& sink) {
  if (s.kind == K::List || s.kind == K::Word) return s.read_value(v, s.name, p, sink);
  const auto n = read_number(s, v, sink);
  if (n) s.set(p, *n);
  return n.has_value();
}

std::optional<BodyDifference> group_difference(const sim::RobotParams& first, const sim::RobotParams& other) {
  const auto differ = [&](std::string_view key) -> std::optional<BodyDifference> {
    const RobotSetting& s = *find_robot_setting(key);
    std::string a = robot_value_text(s, first), b = robot_value_text(s, other);
    if (a == b) return std::nullopt;
    return BodyDifference{std::string(key), false, std::move(a), std::move(b)};
  };
  // What the world steps alike first: a difference there has no remedy but another body. Then
  // what a controller reads, which a controller per body may read apart.
  using Count = std::size_t (*)(const sim::RobotParams&);
  static constexpr std::pair<std::string_view, Count> kCounted[] = {
      {"ir_sensors", [](const sim::RobotParams& p) { return p.ir.mounts.size(); }},
      {"ground_sensors", [](const sim::RobotParams& p) { return p.ground.mounts.size(); }},
      {"rangefinders", [](const sim::RobotParams& p) { return p.rangefinders.angles_rad.size(); }},
      {"bumpers", [](const sim::RobotParams& p) { return p.bumpers.size(); }},
      {"radars", [](const sim::RobotParams& p) { return static_cast<std::size_t>(p.radars); }},
  };
  for (const std::string_view key : {"drive", "control_step", "substeps"})
    if (auto d = differ(key)) return d;
  for (const auto& [key, count] : kCounted)
    if (count(first) != count(other))
      return BodyDifference{std::string(key), true, fmt::format("{}", count(first)), fmt::format("{}", count(other))};
  // A name matters only for sensors the bodies have.
  if (!first.ir.mounts.empty())
    if (auto d = differ("ir_name")) return d;
  if (!first.ground.mounts.empty())
    if (auto d = differ("ground_name")) return d;
  return std::nullopt;
}

std::string group_difference_message(const BodyDifference& d, std::string_view other, std::string_view first) {
  return fmt::format("`{}` has {} `{}` than `{}` ({} against {}): the bodies of a group share {}their drive and their "
                     "control step",
                     other, d.counted ? "another number of" : "another", d.key, first, d.other, d.first,
                     d.sensors() ? "the sensors one controller reads, " : "");
}

std::string robot_value_text(const RobotSetting& s, const sim::RobotParams& p) {
  if (s.kind == K::List || s.kind == K::Word) return s.value_text(p);
  const double v = s.get(p);
  if (s.kind == K::Flag) return v != 0.0 ? "on" : "off";
  if (s.kind == K::Whole) return fmt::format("{}", static_cast<long long>(v));
  return s.dim == Dim::None ? number_text(v) : with_unit(v, s.dim);
}

}  // namespace esc::compiler
