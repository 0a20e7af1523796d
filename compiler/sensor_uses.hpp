#pragma once
// The observables that exist only where an experiment declares their sensor: `goal_distance`
// and `radar[i]` need its arena's `goal`; `radar[i]` also the robot's `radars` (i below their
// count), `range[i]` its `rangefinders` and `ir[i]` and `light[i]` its `ir_sensors` (i below
// their count). Reading one without its
// sensor is an error at the read: an expression of a fitness or behavior (lower_expr.cpp), a
// network input, a GP terminal or a frozen controller in a supervisor (lower_controller.cpp),
// and a `--set` that takes a sensor away (setting_keys.cpp).
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "compiler/resolver.hpp"
#include "compiler/rule_messages.hpp"
#include "runtime/control/controller_spec.hpp"
#include "runtime/eval/experiment.hpp"
#include "runtime/expr/observables.hpp"

namespace esc::compiler {

// What an experiment provides of those sensors.
struct Navigation {
  std::string experiment;   // names, for messages
  std::string arena;
  std::string body;         // a group's body, by name, where its bodies read other sensors
  bool goal = false;
  int rangefinders = 0;
  int radars = 0;
  int ir_sensors = sim::kMaxIrSensors;
  int ground_sensors = 0;
  int bumpers = 0;
  // The names its robot reads its renamable sensors by (robot_settings.hpp), by observable:
  // `ir` -> `prox` on the e-puck; an observable not listed keeps its own name.
  std::map<std::string, std::string, std::less<>> names;
  [[nodiscard]] std::string_view name_of(std::string_view observable) const;
};

// The observable a script's name reads: a built-in one, or a renamable sensor array by any
// name of `names` (null: the built-in names alone).
[[nodiscard]] std::optional<expr::Observable> find_observable(std::string_view name, const SensorNames* names);

// Why `name`, the name of a renamable sensor array a script reads, is not what the robot
// under `n` calls them (a controller written for another body), or nullopt when it is or
// when `name` reads something else.
[[nodiscard]] std::optional<RuleMessage> misnamed(std::string_view name, const Navigation& n, const SensorNames* names);

[[nodiscard]] Navigation navigation_of(const eval::ExperimentSpec& x);
// What body `body` of x's group (ExperimentSpec::bodies) provides, named in messages.
[[nodiscard]] Navigation navigation_of(const eval::ExperimentSpec& x, std::size_t body);

// Why frame slot `slot` cannot be read under `n` (message and help), or nullopt when it can.
[[nodiscard]] std::optional<RuleMessage> unavailable(expr::Slot slot, const Navigation& n);

// The frame slots a fitness reads (its programs), and those a controller reads: its
// network's inputs, its actions' and behaviors' programs, its tree's observable terminals,
// and what the controllers frozen in it read.
[[nodiscard]] std::set<expr::Slot> slots_read(const eval::FitnessSpec& f);
[[nodiscard]] std::set<expr::Slot> slots_read(const control::ControllerSpec& c);
// What an experiment's fitness, further objectives and descriptors read.
[[nodiscard]] std::set<expr::Slot> slots_read_by_measures(const eval::ExperimentSpec& x);

// Why a body of x's group cannot give what is read on it, or nullopt when every body can. The
// measures are read on every body, by the names the first body gives them; a controller per
// body's networks each on its own body, any other controller on every body. The first problem
// found, body by body: the compiler asks it once every read has been checked on the first body
// where it is written (the further bodies' problems, at the group), and a `--set` that may take
// a sensor away asks it again.
[[nodiscard]] std::optional<RuleMessage> unreadable_on_bodies(const eval::ExperimentSpec& x);

}  // namespace esc::compiler
