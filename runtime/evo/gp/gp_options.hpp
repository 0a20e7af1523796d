#pragma once
// GP's options as scripts write them (`evolve gp(population 150, tournament 7)`, `--set
// gp.population=150`; docs/language.md): its own (population, generations, tournament,
// elitism) and the tree operators every algorithm that evolves trees varies them with; and
// the check that they suit a tree controller's primitives.
#include <string>
#include <vector>

#include "runtime/evo/algorithm_options.hpp"
#include "runtime/evo/gp/gp.hpp"

namespace esc::evo::gp {

[[nodiscard]] const std::vector<AlgorithmOption>& gp_options();

// Why GP cannot breed trees of `set` with `settings` (GeneticProgramming's checks, without
// its "genetic programming: " prefix: `max_depth must be in [2, 40] ...`), or "". Without a
// set (settings that evolve no tree), that of a tree of one Number terminal.
[[nodiscard]] std::string gp_problem(const GpSettings& settings, const genome::tree::PrimitiveSet* set);

}  // namespace esc::evo::gp
