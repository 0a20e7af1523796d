#pragma once
// The robot settings (sim::KheperaParams): keyword, kind, dimension, meaning, and how to get
// and set each. One table for robot blocks in scripts, `esc run --set robot.KEY=VALUE`,
// resolved settings and the documentation. The table holds no limits of its own beyond
// the syntax (a whole number, a flag): the ranges are the runtime's rules
// (runtime/sim/validate.hpp), which the compiler applies to the finished robot.
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "compiler/ast.hpp"
#include "compiler/sink.hpp"
#include "compiler/units.hpp"
#include "runtime/sim/khepera_params.hpp"

namespace esc::compiler {

struct RobotSetting {
  std::string_view name;
  // Angles: a list of angles (`[90deg, 0deg, -90deg]`, `[]` for none), read and written by
  // `get_angles` and `set_angles`; the other kinds are one number, by `get` and `set`.
  enum class Kind { Flag, Quantity, Whole, Angles } kind;
  Dim dim;
  std::string_view summary;
  double (*get)(const sim::KheperaParams&) = nullptr;
  void (*set)(sim::KheperaParams&, double) = nullptr;
  std::span<const double> (*get_angles)(const sim::KheperaParams&) = nullptr;
  void (*set_angles)(sim::KheperaParams&, std::vector<double>) = nullptr;
};

[[nodiscard]] const std::vector<RobotSetting>& robot_settings();
[[nodiscard]] const RobotSetting* find_robot_setting(std::string_view name);
[[nodiscard]] std::vector<std::string> robot_setting_names();

// Reads `v` as setting `s`'s value (SI) into `p`, reporting a mistake at the value; false
// (and `p` unchanged) on a mistake.
[[nodiscard]] bool apply_robot_value(const RobotSetting& s, const ast::Value& v, sim::KheperaParams& p, Sink& sink);

// "0.08 m/s", "on", "3", "[1.5707963267948966 rad, 0 rad]": a setting's current value, for
// resolved settings.
[[nodiscard]] std::string robot_value_text(const RobotSetting& s, const sim::KheperaParams& p);

}  // namespace esc::compiler
