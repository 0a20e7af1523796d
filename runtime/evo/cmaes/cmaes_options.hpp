#pragma once
// CMA-ES's options as scripts write them (`evolve cmaes(lambda 20, separable)`, `--set
// cmaes.sigma=0.3`; docs/language.md), and the check of its settings together.
#include <any>
#include <cstddef>
#include <string>
#include <vector>

#include "runtime/evo/algorithm_options.hpp"
#include "runtime/evo/cmaes/cmaes.hpp"

namespace esc::evo {

[[nodiscard]] const std::vector<AlgorithmOption>& cmaes_options();

// Why CMA-ES cannot run with `settings` (a CmaesSettings) on a network of `genome_size`
// weights (mu above lambda / 2, ...), or "".
[[nodiscard]] std::string cmaes_problem(const CmaesSettings& settings, std::size_t genome_size);

}  // namespace esc::evo
