#pragma once
// NEAT's options as scripts will write them (`evolve neat(population 150, add_node_prob
// 0.03)`, `--set neat.threshold=3`), one row per setting of NeatSettings with its check,
// and the check of the settings together with the problem.
#include <cstddef>
#include <string>
#include <vector>

#include "runtime/evo/algorithm_options.hpp"
#include "runtime/evo/neat/neat_settings.hpp"

namespace esc::evo {

[[nodiscard]] const std::vector<AlgorithmOption>& neat_options();

// Why NEAT cannot run with `settings` on a network of `inputs` inputs and `outputs`
// outputs (a value outside its row's range, no input or output), or "".
[[nodiscard]] std::string neat_problem(const NeatSettings& settings, std::size_t inputs, std::size_t outputs);

}  // namespace esc::evo
