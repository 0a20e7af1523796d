#pragma once
// The options of `evolve cmaes(...)` (runtime/evo/cmaes/cmaes.hpp's CmaesSettings): one
// table for scripts, `esc run --set cmaes.KEY=VALUE`, resolved settings (`cmaes.KEY`) and
// the documentation.
#include <cstddef>
#include <string>
#include <vector>

#include "compiler/option_table.hpp"
#include "runtime/evo/cmaes/cmaes.hpp"

namespace esc::compiler {

using CmaesOption = OptionRow<evo::CmaesSettings>;

[[nodiscard]] const std::vector<CmaesOption>& cmaes_options();

// A problem of the settings together for a network of `genome_size` weights (CMA-ES's own
// checks: mu at most lambda / 2, ...), or "".
[[nodiscard]] std::string cmaes_problem(const evo::CmaesSettings& s, std::size_t genome_size);

}  // namespace esc::compiler
