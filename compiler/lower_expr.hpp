#pragma once
// Expressions -> expr::Program: names resolve to frame slots, units to SI, constant
// subexpressions are folded, and a program deeper than the evaluator's stack is an error.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "compiler/ast.hpp"
#include "compiler/sensor_uses.hpp"
#include "compiler/sink.hpp"
#include "runtime/expr/program.hpp"
#include "runtime/expr/step_aggregate.hpp"

namespace esc::compiler {

// The zones and lights of an experiment's arena, in declaration order: `in(zone)` and
// `reached(light)` read slot first + index.
struct ArenaNames {
  std::string arena;                 // the arena's name, for messages
  std::vector<std::string> zones, lights;
};

// The actions and behaviors of an experiment's compared controllers, as `using(B)`,
// `share(B)` and `count(B)` name them: the usage table's name (`avoid`, `crash_2`) or the
// behavior declared (`useless.crash`), each standing for the experiment-wide choice ids it
// names (control::Choice::id): `avoid` is both the classical and the symbolic library's
// `avoid` when two controllers hold one each, `useless.crash` every listing of it.
struct ChoiceNames {
  std::string experiment;            // for messages
  std::map<std::string, std::vector<int>> ids;
  std::size_t count = 0;             // distinct ids: eval::ExperimentSpec::choice_ids
};

struct ExprScope {
  std::vector<std::string> params;   // behavior parameters, read from slot::param + i
  // The arena `in(...)` / `reached(...)` resolve in. Null outside an experiment: then their
  // argument is only checked to be a name (each experiment lowers the expression again with
  // its arena).
  const ArenaNames* arena = nullptr;
  // What the expression is: a behavior's wheel (no `using`), a fitness's step term or stop
  // condition (`using(B)`), or an end term (`epoch:` / `evaluation:`: also the aggregates
  // `share(B)`, `count(B)` and `steps`).
  enum class Use { Behavior, Step, End } use = Use::Behavior;
  // The choices `using(B)` & co. resolve among. Null outside an experiment: then their
  // argument is only checked to be a name.
  const ChoiceNames* choices = nullptr;
  // The goal and the sensors `goal_distance`, `range[i]` and `radar[i]` need. Null outside
  // an experiment: then they are not checked.
  const Navigation* navigation = nullptr;
  // The names the program's robots read their renamable sensors by (Resolver::sensor_names);
  // null: the built-in names alone. Under a `navigation`, only its robot's names read them.
  const SensorNames* sensor_names = nullptr;
  // Where an end term's step aggregates go (`mean(speed)`, `fraction(collision)`), each read
  // from the slot after the last one's (the first: eval::ExperimentSpec::step_aggregate_slot()).
  // Null where none may be read: a step term, a stop condition, a behavior.
  std::vector<expr::StepAggregate>* step_aggregates = nullptr;
  // The experiment's radii a group's `clusters(15cm)` & co. are counted within, each read from
  // its index's slots (eval::ExperimentSpec::cluster_radii), a new one added. Null outside an
  // experiment: then the radius is only checked (and a behavior may not read them).
  std::vector<double>* cluster_radii = nullptr;
};

// The first slot of an end term's step aggregates among the choices `choices` numbers.
[[nodiscard]] expr::Slot step_aggregate_slot(const ChoiceNames* choices) noexcept;

// Reports errors to `sink`; nullopt when the expression has one.
[[nodiscard]] std::optional<expr::Program> lower_expr(const ast::Expr& e, const ExprScope& scope, Sink& sink);

// The script functions with their arity ("min" -> 2, ...), for docs and suggestions.
[[nodiscard]] std::vector<std::string> function_names();

}  // namespace esc::compiler
