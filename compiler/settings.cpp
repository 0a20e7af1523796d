#include "compiler/settings.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "compiler/compiler.hpp"
#include "compiler/gp_settings.hpp"
#include "compiler/names.hpp"
#include "compiler/quantities.hpp"
#include "runtime/sim/validate.hpp"

namespace esc::compiler {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
using K = RobotSetting::Kind;

}  // namespace

const std::vector<RobotSetting>& robot_settings() {
  static const std::vector<RobotSetting> table = {
      {"inertia", K::Flag, Dim::None, 0, false, 1, "motor inertia on or off",
       [](const sim::KheperaParams& p) { return p.motor.inertia ? 1.0 : 0.0; },
       [](sim::KheperaParams& p, double v) { p.motor.inertia = v != 0.0; }},
      {"max_speed", K::Quantity, Dim::Speed, 0, true, kInf, "wheel speed of command 1.0",
       [](const sim::KheperaParams& p) { return p.motor.max_speed_mps; },
       [](sim::KheperaParams& p, double v) { p.motor.max_speed_mps = v; }},
      {"time_constant", K::Quantity, Dim::Time, 0, false, kInf, "first-order lag of the wheels",
       [](const sim::KheperaParams& p) { return p.motor.time_constant_s; },
       [](sim::KheperaParams& p, double v) { p.motor.time_constant_s = v; }},
      {"max_accel", K::Quantity, Dim::Accel, 0, true, kInf, "acceleration limit of each wheel",
       [](const sim::KheperaParams& p) { return p.motor.max_accel_mps2; },
       [](sim::KheperaParams& p, double v) { p.motor.max_accel_mps2 = v; }},
      {"body_radius", K::Quantity, Dim::Length, 0, true, kInf, "radius of the cylindrical body",
       [](const sim::KheperaParams& p) { return p.body_radius_m; },
       [](sim::KheperaParams& p, double v) { p.body_radius_m = v; }},
      {"body_height", K::Quantity, Dim::Length, 0, true, kInf, "height of the body",
       [](const sim::KheperaParams& p) { return p.body_height_m; },
       [](sim::KheperaParams& p, double v) { p.body_height_m = v; }},
      {"wheel_base", K::Quantity, Dim::Length, 0, true, kInf, "distance between the wheels",
       [](const sim::KheperaParams& p) { return p.wheel_base_m; },
       [](sim::KheperaParams& p, double v) { p.wheel_base_m = v; }},
      {"mass", K::Quantity, Dim::Mass, 0, true, kInf, "mass of the robot",
       [](const sim::KheperaParams& p) { return p.mass_kg; },
       [](sim::KheperaParams& p, double v) { p.mass_kg = v; }},
      {"control_step", K::Quantity, Dim::Time, 0, true, kInf, "duration of one control step",
       [](const sim::KheperaParams& p) { return p.control_step_s; },
       [](sim::KheperaParams& p, double v) { p.control_step_s = v; }},
      {"substeps", K::Whole, Dim::None, 1, false, 1000, "physics steps per control step",
       [](const sim::KheperaParams& p) { return static_cast<double>(p.physics_substeps); },
       [](sim::KheperaParams& p, double v) { p.physics_substeps = static_cast<int>(v); }},
      {"ir_range", K::Quantity, Dim::Length, 0, true, kInf, "IR reading is 0 at and beyond this distance",
       [](const sim::KheperaParams& p) { return p.ir.range_m; },
       [](sim::KheperaParams& p, double v) { p.ir.range_m = v; }},
      {"ir_aperture", K::Quantity, Dim::Angle, 0, false, 2 * std::numbers::pi, "angle spanned by a sensor's rays",
       [](const sim::KheperaParams& p) { return p.ir.aperture_rad; },
       [](sim::KheperaParams& p, double v) { p.ir.aperture_rad = v; }},
      {"ir_rays", K::Whole, Dim::None, 1, false, 64, "rays per IR sensor",
       [](const sim::KheperaParams& p) { return static_cast<double>(p.ir.rays); },
       [](sim::KheperaParams& p, double v) { p.ir.rays = static_cast<int>(v); }},
      {"ir_noise", K::Quantity, Dim::None, 0, false, kInf, "standard deviation of IR noise (readings 0..1)",
       [](const sim::KheperaParams& p) { return p.ir.noise_sd; },
       [](sim::KheperaParams& p, double v) { p.ir.noise_sd = v; }},
      {"light_half_distance", K::Quantity, Dim::Length, 0, true, kInf,
       "a unit light straight ahead at this distance reads 0.5",
       [](const sim::KheperaParams& p) { return p.light.half_distance_m; },
       [](sim::KheperaParams& p, double v) { p.light.half_distance_m = v; }},
      {"light_noise", K::Quantity, Dim::None, 0, false, kInf, "standard deviation of light noise (readings 0..1)",
       [](const sim::KheperaParams& p) { return p.light.noise_sd; },
       [](sim::KheperaParams& p, double v) { p.light.noise_sd = v; }},
      {"energy", K::Flag, Dim::None, 0, false, 1, "energy accumulator on or off",
       [](const sim::KheperaParams& p) { return p.energy.enabled ? 1.0 : 0.0; },
       [](sim::KheperaParams& p, double v) { p.energy.enabled = v != 0.0; }},
      {"energy_discharge", K::Whole, Dim::None, 1, false, 100000000, "control steps from full to empty",
       [](const sim::KheperaParams& p) { return static_cast<double>(p.energy.discharge_steps); },
       [](sim::KheperaParams& p, double v) { p.energy.discharge_steps = static_cast<int>(v); }},
      {"energy_recharge", K::Whole, Dim::None, 1, false, 100000000, "control steps from empty to full in a recharge zone",
       [](const sim::KheperaParams& p) { return static_cast<double>(p.energy.recharge_steps); },
       [](sim::KheperaParams& p, double v) { p.energy.recharge_steps = static_cast<int>(v); }},
  };
  return table;
}

const RobotSetting* find_robot_setting(std::string_view name) {
  for (const RobotSetting& s : robot_settings())
    if (s.name == name) return &s;
  return nullptr;
}

std::vector<std::string> robot_setting_names() {
  std::vector<std::string> v;
  for (const RobotSetting& s : robot_settings()) v.emplace_back(s.name);
  return v;
}

std::string robot_value_text(const RobotSetting& s, const sim::KheperaParams& p) {
  const double v = s.get(p);
  if (s.kind == K::Flag) return v != 0.0 ? "on" : "off";
  if (s.kind == K::Whole) return fmt::format("{}", static_cast<long long>(v));
  const std::string_view u = si_unit(s.dim);
  return u.empty() ? number_text(v) : fmt::format("{} {}", number_text(v), u);
}

std::string check_robot_value(const RobotSetting& s, double si) {
  const std::string_view u = si_unit(s.dim);
  auto shown = [&](double v) { return u.empty() ? number_text(v) : fmt::format("{} {}", number_text(v), u); };
  if (s.min_exclusive ? !(si > s.min) : !(si >= s.min))
    return fmt::format("`{}` must be {} {}, found {}", s.name, s.min_exclusive ? "greater than" : "at least",
                       shown(s.min), shown(si));
  if (si > s.max) return fmt::format("`{}` must be at most {}, found {}", s.name, shown(s.max), shown(si));
  return {};
}

SettingValue read_robot_value(const RobotSetting& s, bool is_flag, bool flag, double number,
                              std::string_view text, std::string_view unit) {
  SettingValue out;
  if (s.kind == K::Flag) {
    if (!is_flag) {
      out.message = fmt::format("`{}` is `on` or `off`, found `{}{}`", s.name, text, unit);
      out.help = fmt::format("write `{} on` or `{} off`", s.name, s.name);
      return out;
    }
    out.ok = true;
    out.si = flag ? 1.0 : 0.0;
    return out;
  }
  if (is_flag) {
    out.message = fmt::format("`{}` takes {}, found `{}`", s.name,
                              s.kind == K::Whole ? "a whole number" : dim_phrase(s.dim), flag ? "on" : "off");
    return out;
  }
  Reading r = s.kind == K::Whole
                  ? read_whole(number, text, unit, fmt::format("`{}`", s.name), static_cast<long long>(s.min),
                               static_cast<long long>(s.max))
                  : read_quantity(number, text, unit, s.dim);
  if (!r.ok) {
    out.message = r.message;
    out.help = r.help;
    return out;
  }
  if (std::string m = check_robot_value(s, r.si); !m.empty()) {
    out.message = m;
    return out;
  }
  out.ok = true;
  out.si = r.si;
  return out;
}

std::string check_robot(const sim::KheperaParams& p) {
  if (p.wheel_base_m > 2 * p.body_radius_m)
    return fmt::format("the wheel base ({} m) is wider than the body ({} m across)", number_text(p.wheel_base_m),
                       number_text(2 * p.body_radius_m));
  // The contact solver only sees walls a limited distance ahead of the moving body.
  const double travel_m = p.motor.max_speed_mps * p.control_step_s / p.physics_substeps;
  if (travel_m > sim::kMaxTravelPerSubstep_m) {
    const auto needed = static_cast<int>(std::ceil(p.motor.max_speed_mps * p.control_step_s / sim::kMaxTravelPerSubstep_m));
    return fmt::format("at full speed the robot moves {} mm per physics substep, more than the {} mm the contact "
                       "solver looks ahead: use `substeps {}` or more, or a lower `max_speed`",
                       number_text(travel_m * 1000), number_text(sim::kMaxTravelPerSubstep_m * 1000), needed);
  }
  return {};
}

std::string check_es(const evo::EsSettings& es) {
  if (es.mu < 1) return fmt::format("`mu` must be at least 1, found {}", es.mu);
  if (es.lambda < 1) return fmt::format("`lambda` must be at least 1, found {}", es.lambda);
  if (es.selection == evo::Selection::Comma && es.lambda < es.mu)
    return fmt::format("comma selection needs `lambda` >= `mu`, found mu {} and lambda {}", es.mu, es.lambda);
  if (!(es.lower < es.upper))
    return fmt::format("`bounds` must have lower < upper, found [{}, {}]", number_text(es.lower),
                       number_text(es.upper));
  if (!(es.initial_sigma > 0)) return fmt::format("`sigma` must be greater than 0, found {}", number_text(es.initial_sigma));
  if (es.generations < 1) return fmt::format("`generations` must be at least 1, found {}", es.generations);
  return {};
}

void resolve_settings(eval::ExperimentSpec& spec) {
  auto& r = spec.resolved_settings;
  r["experiment"] = spec.name;
  r["epochs"] = std::to_string(spec.epochs);
  r["steps"] = std::to_string(spec.steps);
  r["runs"] = std::to_string(spec.runs);
  r["seed"] = std::to_string(spec.seed);
  const evo::EsSettings& es = spec.es;
  r["generations"] = std::to_string(spec.es_generations());
  if (spec.start_from)
    r["start_from"] = fmt::format("{} from experiment {}", spec.start_from->evaluate_only ? "evaluate" : "start",
                                  spec.start_from->experiment);
  r["mu"] = std::to_string(es.mu);
  r["lambda"] = std::to_string(es.lambda);
  r["selection"] = es.selection == evo::Selection::Comma ? "comma" : "plus";
  r["recombination"] = es.recombination == evo::Recombination::Intermediate ? "intermediate"
                       : es.recombination == evo::Recombination::Discrete   ? "discrete"
                                                                            : "none";
  r["step_sizes"] = es.step_sizes == evo::StepSizes::PerGene ? "self_adaptive" : "one_sigma";
  r["bounds"] = fmt::format("[{}, {}]", number_text(es.lower), number_text(es.upper));
  r["sigma"] = number_text(es.initial_sigma);
  r["min_sigma"] = number_text(es.min_sigma);
  r["arena"] = spec.arena_name;
  r["arena.size"] = fmt::format("{} m x {} m", number_text(spec.arena.width_m), number_text(spec.arena.height_m));
  r["arena.cylinders"] = std::to_string(spec.arena.cylinders.size());
  r["arena.blocks"] = std::to_string(spec.arena.boxes.size());
  r["arena.lights"] = std::to_string(spec.arena.lights.size());
  r["arena.zones"] = std::to_string(spec.arena.zones.size());
  r["arena.sweep_cell"] = fmt::format("{} m", number_text(spec.arena.sweep_cell_m));
  r["arena.reach_radius"] = fmt::format("{} m", number_text(spec.arena.reach_radius_m));
  if (spec.arena.fixed_start)
    r["arena.start"] = fmt::format("({} m, {} m) heading {} rad", number_text(spec.arena.fixed_start->x_m),
                                   number_text(spec.arena.fixed_start->y_m),
                                   number_text(spec.arena.fixed_start->heading_rad));
  else
    r["arena.start"] = "random";
  for (const RobotSetting& s : robot_settings())
    r["robot." + std::string(s.name)] = robot_value_text(s, spec.robot);
  r["fitness"] = spec.fitness.name;
  std::string names;
  for (const auto& c : spec.controllers) names += (names.empty() ? "" : ", ") + c.name;
  r["compare"] = names;
  resolve_gp_settings(spec);
}

namespace {

const std::vector<std::string>& setting_keys() {
  static const std::vector<std::string> keys = [] {
    std::vector<std::string> k = {"epochs", "steps", "runs", "seed", "generations", "mu", "lambda",
                                  "selection", "recombination", "step_sizes", "sigma", "bounds"};
    for (const RobotSetting& s : robot_settings()) k.push_back("robot." + std::string(s.name));
    for (const std::string& g : gp_option_names()) k.push_back("gp." + g);
    return k;
  }();
  return keys;
}

std::string all_keys() {
  std::string s;
  for (const std::string& k : setting_keys()) s += (s.empty() ? "" : ", ") + k;
  return s;
}

std::string trim(std::string_view v) {
  while (!v.empty() && (v.front() == ' ' || v.front() == '\t')) v.remove_prefix(1);
  while (!v.empty() && (v.back() == ' ' || v.back() == '\t')) v.remove_suffix(1);
  return std::string(v);
}

// Reads a whole number for `key`; returns a message on failure.
std::string whole(std::string_view key, std::string_view value, long long min, long long max, long long& out) {
  double v = 0;
  std::string unit;
  if (!split_value(value, v, unit)) return fmt::format("`{}` takes a whole number, found `{}`", key, value);
  const Reading r = read_whole(v, trim(value.substr(0, value.size() - 0)), unit, fmt::format("`{}`", key), min, max);
  if (!r.ok) return r.message;
  out = static_cast<long long>(r.si);
  return {};
}

}  // namespace

std::string apply_setting(eval::ExperimentSpec& experiment, std::string_view key_in, std::string_view value_in) {
  const std::string key = trim(key_in);
  const std::string value = trim(value_in);
  eval::ExperimentSpec spec = experiment;   // commit only when everything checks
  constexpr long long kIntMax = std::numeric_limits<int>::max();
  long long n = 0;
  std::string err;
  if (key == "epochs") {
    if ((err = whole(key, value, 1, kIntMax, n)).empty()) spec.epochs = static_cast<int>(n);
  } else if (key == "steps") {
    if ((err = whole(key, value, 1, kIntMax, n)).empty()) spec.steps = static_cast<int>(n);
  } else if (key == "runs") {
    if ((err = whole(key, value, 1, kIntMax, n)).empty()) spec.runs = static_cast<int>(n);
  } else if (key == "seed") {
    if ((err = whole(key, value, 0, (1LL << 53), n)).empty()) spec.seed = static_cast<std::uint64_t>(n);
  } else if (key == "generations") {   // of the ES and of the GP alike
    if ((err = whole(key, value, 1, kIntMax, n)).empty()) {
      spec.es.generations = static_cast<int>(n);
      if (spec.gp) spec.gp->generations = static_cast<int>(n);
    }
  } else if (key == "mu") {
    if ((err = whole(key, value, 1, kIntMax, n)).empty()) spec.es.mu = static_cast<int>(n);
  } else if (key == "lambda") {
    if ((err = whole(key, value, 1, kIntMax, n)).empty()) spec.es.lambda = static_cast<int>(n);
  } else if (key == "selection") {
    if (value == "comma") spec.es.selection = evo::Selection::Comma;
    else if (value == "plus") spec.es.selection = evo::Selection::Plus;
    else err = fmt::format("`selection` is `comma` or `plus`, found `{}`", value);
  } else if (key == "recombination") {
    if (value == "intermediate") spec.es.recombination = evo::Recombination::Intermediate;
    else if (value == "discrete") spec.es.recombination = evo::Recombination::Discrete;
    else if (value == "none" || value == "no_recombination") spec.es.recombination = evo::Recombination::None;
    else err = fmt::format("`recombination` is `intermediate`, `discrete` or `none`, found `{}`", value);
  } else if (key == "step_sizes") {
    if (value == "self_adaptive" || value == "per_gene") spec.es.step_sizes = evo::StepSizes::PerGene;
    else if (value == "one_sigma" || value == "one") spec.es.step_sizes = evo::StepSizes::One;
    else err = fmt::format("`step_sizes` is `self_adaptive` or `one_sigma`, found `{}`", value);
  } else if (key == "sigma") {
    double v = 0;
    std::string unit;
    if (!split_value(value, v, unit) || !unit.empty())
      err = fmt::format("`sigma` takes a plain number, found `{}`", value);
    else
      spec.es.initial_sigma = v;
  } else if (key == "bounds") {
    std::string v = value;
    if (!v.empty() && v.front() == '[') v.erase(0, 1);
    if (!v.empty() && v.back() == ']') v.pop_back();
    const std::size_t comma = v.find(',');
    double lo = 0, hi = 0;
    std::string u1, u2;
    if (comma == std::string::npos || !split_value(v.substr(0, comma), lo, u1) ||
        !split_value(v.substr(comma + 1), hi, u2) || !u1.empty() || !u2.empty())
      err = fmt::format("`bounds` takes two numbers, as in `[-1, 1]`, found `{}`", value);
    else {
      spec.es.lower = lo;
      spec.es.upper = hi;
    }
  } else if (key.rfind("gp.", 0) == 0) {
    err = apply_gp_setting(spec, key.substr(3), value);
  } else if (key.rfind("robot.", 0) == 0) {
    const std::string name = key.substr(6);
    const RobotSetting* s = find_robot_setting(name);
    if (s == nullptr) {
      err = fmt::format("unknown robot setting `{}`", name);
      if (auto best = closest(name, robot_setting_names())) err += fmt::format("; did you mean `robot.{}`?", *best);
      err += fmt::format(" (robot settings: {})", fmt::join(robot_setting_names(), ", "));
    } else {
      const bool is_flag = value == "on" || value == "off" || value == "true" || value == "false";
      const bool flag = value == "on" || value == "true";
      double v = 0;
      std::string unit;
      if (!is_flag && !split_value(value, v, unit)) {
        err = fmt::format("`{}` takes {}, found `{}`", key,
                          s->kind == RobotSetting::Kind::Flag    ? "`on` or `off`"
                          : s->kind == RobotSetting::Kind::Whole ? "a whole number"
                                                                 : dim_phrase(s->dim),
                          value);
      } else {
        std::string num = value.substr(0, value.size() - std::min(value.size(), unit.size()));
        num = trim(num);
        const SettingValue sv = read_robot_value(*s, is_flag, flag, v, num, unit);
        if (!sv.ok) err = sv.message + (sv.help.empty() ? "" : " (" + sv.help + ")");
        else s->set(spec.robot, sv.si);
      }
    }
  } else {
    err = fmt::format("unknown setting `{}`", key);
    if (auto best = closest(key, setting_keys())) err += fmt::format("; did you mean `{}`?", *best);
    err += fmt::format(" (settings: {})", all_keys());
  }
  if (!err.empty()) return err;
  if (std::string m = check_es(spec.es); !m.empty()) return m;
  if (std::string m = check_gp(spec); !m.empty()) return m;
  if (std::string m = check_robot(spec.robot); !m.empty()) return m;
  resolve_settings(spec);
  experiment = std::move(spec);
  return {};
}

}  // namespace esc::compiler
