#pragma once
// What the fuzz targets require of every experiment the compiler accepts: the checks the
// runtime makes before running it pass (an abort, which libFuzzer reports with the input,
// otherwise).
#include <cstdlib>
#include <exception>

#include "runtime/eval/experiment.hpp"
#include "runtime/evo/es/es.hpp"
#include "runtime/evo/gp/gp.hpp"
#include "runtime/sim/validate.hpp"

namespace esc::fuzz {

inline void require_runnable(const eval::ExperimentSpec& x) {
  try {
    sim::validate_arena(x.arena);
    sim::validate_robot(x.robot);
    for (const control::ControllerSpec& c : x.controllers) {
      if (c.is_tree()) {
        if (!x.gp || c.primitives == nullptr) std::abort();
        (void)evo::gp::GeneticProgramming(*x.gp, *c.primitives);
      } else {
        (void)evo::EvolutionStrategy(x.es, c.genome_size());
      }
    }
  } catch (const std::exception&) {
    std::abort();   // accepted by the compiler, refused by the runtime
  }
}

}  // namespace esc::fuzz
