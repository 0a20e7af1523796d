#pragma once
// The robot settings (sim::KheperaParams): keyword, kind, dimension, meaning, and how to get
// and set each. One table for robot blocks in scripts, `esc run --set robot.KEY=VALUE`,
// resolved settings and the documentation. The table holds no limits of its own beyond
// the syntax (a whole number, a flag): the ranges are the runtime's rules
// (runtime/sim/validate.hpp), which the compiler applies to the finished robot.
#include <optional>
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
  enum class Kind { Flag, Quantity, Whole } kind;
  Dim dim;
  std::string_view summary;
  double (*get)(const sim::KheperaParams&);
  void (*set)(sim::KheperaParams&, double);
};

[[nodiscard]] const std::vector<RobotSetting>& robot_settings();
[[nodiscard]] const RobotSetting* find_robot_setting(std::string_view name);
[[nodiscard]] std::vector<std::string> robot_setting_names();

// Reads `v` as setting `s`'s value (SI; a flag is 0 or 1), reporting a mistake at the value.
[[nodiscard]] std::optional<double> read_robot_value(const RobotSetting& s, const ast::Value& v, Sink& sink);

// "0.08 m/s", "on", "3": a setting's current value, for resolved settings.
[[nodiscard]] std::string robot_value_text(const RobotSetting& s, const sim::KheperaParams& p);

}  // namespace esc::compiler
