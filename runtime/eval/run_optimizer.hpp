#pragma once
// The optimizer of one run of a compared controller, as the run loop makes it and as a
// replay rebuilds it from a stored state: the algorithm the experiment evolves the
// controller by (or evaluation alone), with the name and format its state is stored under.
#include <cstdint>
#include <memory>

#include "runtime/eval/experiment.hpp"
#include "runtime/eval/run_state.hpp"

namespace esc::eval {

struct RunOptimizer {
  std::unique_ptr<evo::Optimizer> optimizer;
  OptimizerState empty_state;   // its algorithm and format, no bytes
};

// Throws std::invalid_argument naming the controller when the experiment has no such
// algorithm or no settings for it, or the settings cannot run on `problem`.
[[nodiscard]] RunOptimizer make_run_optimizer(const ExperimentSpec& spec, const control::ControllerSpec& controller,
                                              const evo::Problem& problem);

// Loads `stored` into `made`'s optimizer. Throws std::invalid_argument naming the controller
// when another algorithm or format saved it, or its optimizer could not have saved the bytes.
void load_run_state(RunOptimizer& made, const control::ControllerSpec& controller, const OptimizerState& stored);

}  // namespace esc::eval
