#pragma once
// An experiment's objectives and behavior descriptors: `fitness F in [lo, hi]`,
// `objective G minimize in [lo, hi]` and `descriptor NAME: EXPR in [lo, hi] by REDUCTION`
// -> eval::ExperimentSpec's objectives, further and descriptors. Lowered in the experiment's
// arena and among its controllers' choices, as its fitness is.
#include <optional>
#include <string>
#include <vector>

#include "compiler/ast.hpp"
#include "compiler/lower_arena.hpp"
#include "compiler/lower_expr.hpp"
#include "compiler/lower_fitness.hpp"
#include "compiler/resolver.hpp"
#include "compiler/sensor_uses.hpp"
#include "compiler/sink.hpp"
#include "runtime/eval/experiment.hpp"

namespace esc::compiler {

// The items of an experiment that declare its objectives and descriptors, in order.
struct ObjectiveItems {
  const ast::ExpItem* fitness = nullptr;
  std::vector<const ast::ExpItem*> objectives;
  std::vector<const ast::ExpItem*> descriptors;
};

// A value of an objective or a descriptor (a range's bound, a success threshold) in SI,
// whatever its unit: their dimension is their expression's, which expressions do not track.
// None when the number overflowed or its unit is unknown (reported).
[[nodiscard]] std::optional<double> value_in_si(const ast::Quantity& q, Sink& sink);

// The reductions `by` names, in eval::Reduction's order.
[[nodiscard]] const std::vector<std::string>& reduction_names();

// Fills x.objectives, x.further and x.descriptors (x.fitness is lowered already); reports
// every mistake. False when one was found.
// `navigation` says which sensors the experiment has (a descriptor reading `radar` needs a goal).
bool lower_objectives(const ObjectiveItems& items, const ast::ExperimentDecl& experiment,
                      const ast::ArenaDecl& arena, const ChoiceNames& choices, const Navigation& navigation,
                      Resolver& names, FitnessLowering& fitnesses, ArenaLowering& arenas, Sink& sink,
                      eval::ExperimentSpec& x);

// Their resolved settings ("objectives" -> "speed in [0, 1500]; energy minimize in [0, 300]",
// "descriptors" -> ...), added only when declared so that other experiments resolve as before.
void resolve_objectives(eval::ExperimentSpec& x, const ObjectiveItems& items);

}  // namespace esc::compiler
