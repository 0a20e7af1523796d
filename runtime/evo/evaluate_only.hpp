#pragma once
// The optimizer of a run that only evaluates a stored genome (`evaluate from experiment E`):
// one generation, whose one candidate is that genome. It draws nothing and has no state.
#include <memory>

#include "runtime/evo/optimizer.hpp"

namespace esc::evo {

// Throws std::invalid_argument when the problem has no start genome.
[[nodiscard]] std::unique_ptr<Optimizer> make_evaluate_only(const Problem& problem);

}  // namespace esc::evo
