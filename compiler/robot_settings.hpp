#pragma once
// The robot settings (sim::RobotParams): keyword, kind, dimension, meaning, and how to get
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
#include "runtime/sim/robot_params.hpp"

namespace esc::compiler {

struct RobotSetting {
  std::string_view name;
  // Flag, Quantity and Whole are one number, got and set by `get` and `set`; List is a list
  // (`rangefinders [90deg, 0deg]`, `ir_sensors [(68deg, 90deg), ...]`) and Word a word
  // (`ir_name prox`, `drive acceleration`), read from the value as written (reporting its
  // mistakes) by `read_value` and shown by `value_text`.
  enum class Kind { Flag, Quantity, Whole, List, Word } kind;
  Dim dim;   // of a number; of a list's first item
  std::string_view summary;
  double (*get)(const sim::RobotParams&) = nullptr;
  void (*set)(sim::RobotParams&, double) = nullptr;
  bool (*read_value)(const ast::Value&, std::string_view name, sim::RobotParams&, Sink&) = nullptr;
  std::string (*value_text)(const sim::RobotParams&) = nullptr;
  // Names scripts read by are resolved when the script compiles: such a setting is set in a
  // robot block, not by `--set`.
  bool script_only = false;
  [[nodiscard]] bool settable_later() const noexcept { return !script_only; }
};

// Sensor arrays a robot may name for scripts (the e-puck's `prox`, the Thymio's
// `prox_horizontal` and `prox_ground`): the setting that names them, which the resolver reads
// from the syntax tree before any robot is lowered (Resolver::sensor_names), the observable
// they read, and what they are, for messages.
struct RenamableSensors {
  std::string_view setting;
  std::string_view observable;
  std::string_view what;
};
inline constexpr RenamableSensors kRenamableSensors[] = {
    {"ir_name", "ir", "IR sensors"},
    {"ground_name", "ground_sensor", "ground sensors"},
};

[[nodiscard]] const std::vector<RobotSetting>& robot_settings();
[[nodiscard]] const RobotSetting* find_robot_setting(std::string_view name);
[[nodiscard]] std::vector<std::string> robot_setting_names();

// Reads `v` as setting `s`'s value (SI) into `p`, reporting a mistake at the value; false
// (and `p` unchanged) on a mistake.
[[nodiscard]] bool apply_robot_value(const RobotSetting& s, const ast::Value& v, sim::RobotParams& p, Sink& sink);

// "0.08 m/s", "on", "3", "[1.5707963267948966 rad, 0 rad]", "[(1.18 rad, 1.57 rad), ...]": a
// setting's current value, for resolved settings.
[[nodiscard]] std::string robot_value_text(const RobotSetting& s, const sim::RobotParams& p);

// How a group's further body differs from its first where the bodies of one group must agree,
// in this order: the drive, the control step and the substeps (one world steps them all), then
// the sensors one controller reads (the number of each kind, then the IR and ground sensors'
// names where there are some), which a controller per body may read apart. Where each sensor
// sits, the body's radius and outline, speeds, ranges, curves and noise may differ: every robot
// is stepped and sensed with its own body, and the replay draws each one's shape.
struct BodyDifference {
  std::string key;             // the robot setting
  bool counted = false;        // the number of sensors `key` lists differs, not its text
  std::string first, other;    // the two values, as a message gives them
  // A difference in what a controller reads (a count or a sensor name), not in the world's step.
  [[nodiscard]] bool sensors() const noexcept { return counted || key.ends_with("_name"); }
};
[[nodiscard]] std::optional<BodyDifference> group_difference(const sim::RobotParams& first,
                                                             const sim::RobotParams& other);
// "`lit` has another `control_step` than `khepera` (0.2 s against 0.1 s): the bodies of a group
// share their drive and their control step": the error for `d` between a further body `other`
// and the group's first body `first`.
[[nodiscard]] std::string group_difference_message(const BodyDifference& d, std::string_view other,
                                                   std::string_view first);

}  // namespace esc::compiler
