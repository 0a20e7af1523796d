#pragma once
// The options of `map_elites` and `cvt_map_elites` as scripts write them
// (`evolve map_elites(bins 20, batch 100)`, `--set cvt_map_elites.cells=1000`;
// docs/language.md).
#include <vector>

#include "runtime/evo/algorithm_options.hpp"

namespace esc::evo {

[[nodiscard]] const std::vector<AlgorithmOption>& map_elites_options();
[[nodiscard]] const std::vector<AlgorithmOption>& cvt_map_elites_options();

}  // namespace esc::evo
