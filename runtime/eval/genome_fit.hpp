#pragma once
// Whether a stored genome (a dependency's best, a replayed run's) fits a controller of an
// experiment: checked before it is evaluated, so that a mismatch is a sentence, not a throw
// from deep in the evaluator.
#include <span>
#include <string>
#include <string_view>

#include "runtime/control/controller_spec.hpp"

namespace esc::eval {

// Why `genome` cannot be controller `c`'s with `roles` networks in one genome ("" when it
// can): a network's weights must be its network's times `roles` (ExperimentSpec::
// genome_length), a tree a well-typed tree of its primitive set, a graph a graph genome of its
// NEAT network's inputs and outputs.
// `evolved`, where known, is the architecture of the controller that evolved it, as stored:
// then a genome that fits in length must also fit in layout (layout_problem).
[[nodiscard]] std::string genome_problem(const control::ControllerSpec& c, std::span<const double> genome, int roles = 1,
                                         std::string_view evolved = {});

// Why a genome evolved by a controller of architecture `evolved` (as stored) cannot be read by
// `c` although its length fits ("" when it can): a controller per body's genome holds its
// networks in its declaration's order, so another order (or other bodies) reads the weights
// of one body's network as another's. Only where either is a controller per body.
[[nodiscard]] std::string layout_problem(const control::ControllerSpec& c, std::string_view evolved);

}  // namespace esc::eval
