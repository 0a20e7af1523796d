#include "runtime/evo/nsga2/nsga2_options.hpp"

#include <cmath>

#include "runtime/genome/tree/tree_variation.hpp"
#include "runtime/evo/nsga2/nsga2_optimizer.hpp"

namespace esc::evo {

const std::vector<AlgorithmOption>& nsga2_options() {
  static const std::vector<AlgorithmOption> table = nsga2_variation_options<Nsga2Settings>();
  return table;
}

std::string nsga2_problem(const Nsga2Settings& settings, const Problem& problem) {
  if (std::string why = genome::tree::tree_problem(problem, "NSGA-II"); !why.empty()) return why;
  if (std::string why = rejection([&] { check_nsga2_settings(settings); }, "NSGA-II: "); !why.empty()) return why;
  // The hypervolume metric spans the declared ranges: their product must be a number.
  if (!hypervolume_reference(problem).empty()) {
    double volume = 1.0;
    for (const Bounds& b : problem.objectives) volume *= b.upper - b.lower;
    if (!std::isfinite(volume))
      return "the hypervolume of the objectives' declared ranges (the product of their widths) overflows a double; "
             "declare narrower ranges";
  }
  return {};
}

}  // namespace esc::evo
