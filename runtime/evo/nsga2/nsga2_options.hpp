#pragma once
// NSGA-II's options as scripts write them (`evolve nsga2(population 100, eta_crossover 20)`,
// `--set nsga2.mutation=0.05`; docs/language.md), and the check of its settings together.
#include <string>
#include <vector>

#include "runtime/evo/algorithm_options.hpp"
#include "runtime/evo/nsga2/nsga2.hpp"
#include "runtime/evo/optimizer.hpp"

namespace esc::evo {

[[nodiscard]] const std::vector<AlgorithmOption>& nsga2_options();

// Why NSGA-II cannot run with `settings` on `problem` (an odd population, ...), or "".
[[nodiscard]] std::string nsga2_problem(const Nsga2Settings& settings, const Problem& problem);

}  // namespace esc::evo
