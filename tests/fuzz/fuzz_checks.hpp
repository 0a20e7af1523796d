#pragma once
// What the fuzz targets require of every experiment the compiler accepts: the checks the
// runtime makes before running it pass (an abort, which libFuzzer reports with the input,
// otherwise).
#include <any>
#include <cstdlib>
#include <exception>

#include "runtime/eval/experiment.hpp"
#include "runtime/evo/es/es.hpp"
#include "runtime/evo/gp/gp.hpp"
#include "runtime/evo/registry.hpp"
#include "runtime/sim/validate.hpp"

namespace esc::fuzz {

inline void require_runnable(const eval::ExperimentSpec& x) {
  try {
    sim::validate_arena(x.arena);
    sim::validate_robot(x.robot);
    for (const control::ControllerSpec& c : x.controllers) {
      if (c.is_tree()) {
        if (x.tree_operators() == nullptr || c.primitives == nullptr) std::abort();
        (void)evo::gp::GeneticProgramming(*x.tree_operators(), *c.primitives);
        continue;
      }
      const eval::Evolution e = x.evolution_of(c);
      if (e.algorithm == nullptr) std::abort();
      if (const auto* es = std::any_cast<evo::EsSettings>(&e.settings)) {
        (void)evo::EvolutionStrategy(*es, c.genome_size());
        continue;
      }
      // Another algorithm (NEAT for a `neat(...)` network, CMA-ES, ...): its settings, or its
      // defaults when the script gives none, as the run takes them, fit the controller.
      const std::any settings = e.settings.has_value() ? e.settings : e.algorithm->defaults();
      if (!e.algorithm->problem(settings, x.problem_of(c)).empty()) std::abort();
    }
  } catch (const std::exception&) {
    std::abort();   // accepted by the compiler, refused by the runtime
  }
}

}  // namespace esc::fuzz
