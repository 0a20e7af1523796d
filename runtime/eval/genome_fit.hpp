#pragma once
// Whether a stored genome (a dependency's best, a replayed run's) fits a controller of an
// experiment: checked before it is evaluated, so that a mismatch is a sentence, not a throw
// from deep in the evaluator.
#include <span>
#include <string>

#include "runtime/control/controller_spec.hpp"

namespace esc::eval {

// Why `genome` cannot be controller `c`'s with `roles` networks in one genome ("" when it
// can): a network's weights must be its network's times `roles` (ExperimentSpec::
// genome_length), a tree a well-typed tree of its primitive set, a graph a graph genome of its
// NEAT network's inputs and outputs.
[[nodiscard]] std::string genome_problem(const control::ControllerSpec& c, std::span<const double> genome, int roles = 1);

}  // namespace esc::eval
