#pragma once
// Novelty search's options as scripts write them (`evolve novelty(k 15, novelty_fitness)`,
// `--set novelty.threshold=0.05`; docs/language.md).
#include <vector>

#include "runtime/evo/algorithm_options.hpp"

namespace esc::evo {

[[nodiscard]] const std::vector<AlgorithmOption>& novelty_options();

}  // namespace esc::evo
