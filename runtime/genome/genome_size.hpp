#pragma once
// What memory estimates count per candidate, whatever kind of genome a problem evolves: the
// algorithms that take several kinds (NSGA-II, MAP-Elites, novelty search) ask here rather
// than one kind's folder knowing the others'.
#include <cstddef>

#include "runtime/evo/optimizer.hpp"

namespace esc::genome {

// Values per genome at most: a network's weights, an encoded tree of the GP's max_size, or a
// graph genome grown to twice its start's links.
[[nodiscard]] std::size_t genes_at_most(const evo::Problem& problem);

}  // namespace esc::genome
