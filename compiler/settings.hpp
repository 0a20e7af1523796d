#pragma once
// The settable parameters: robot settings (names, dimensions, limits), ES settings checks,
// the resolved-settings text of an experiment, and `apply_setting` (compiler.hpp).
#include <string>
#include <string_view>
#include <vector>

#include "compiler/units.hpp"
#include "runtime/eval/experiment.hpp"

namespace esc::compiler {

struct RobotSetting {
  std::string_view name;
  enum class Kind { Flag, Quantity, Whole } kind;
  Dim dim;
  double min;             // inclusive unless min_exclusive
  bool min_exclusive;
  double max;             // inclusive
  std::string_view summary;
  double (*get)(const sim::KheperaParams&);
  void (*set)(sim::KheperaParams&, double);
};

[[nodiscard]] const std::vector<RobotSetting>& robot_settings();
[[nodiscard]] const RobotSetting* find_robot_setting(std::string_view name);
[[nodiscard]] std::vector<std::string> robot_setting_names();

// Checks a value (SI) against the setting's limits: empty when fine, else a message.
[[nodiscard]] std::string check_robot_value(const RobotSetting& s, double si);

// Reads a written setting value ("on", "50ms", "0.5 m/s^2") for setting `s`.
struct SettingValue {
  bool ok = false;
  double si = 0.0;
  std::string message, help;
};
[[nodiscard]] SettingValue read_robot_value(const RobotSetting& s, bool is_flag, bool flag, double number,
                                            std::string_view number_text, std::string_view unit);

// Whole-robot consistency (wheel base within the body, ...): empty when fine.
[[nodiscard]] std::string check_robot(const sim::KheperaParams& p);

// ES consistency (comma needs lambda >= mu, lower < upper, ...): empty when fine.
[[nodiscard]] std::string check_es(const evo::EsSettings& es);

// Rewrites the keys of resolved_settings that the spec's fields determine; keeps the others
// (robot name, fitness sources).
void resolve_settings(eval::ExperimentSpec& spec);

// "0.08 m/s" for a robot setting's current value.
[[nodiscard]] std::string robot_value_text(const RobotSetting& s, const sim::KheperaParams& p);

}  // namespace esc::compiler
