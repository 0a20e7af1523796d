#pragma once
// Estimates what a script's campaign costs before it is run: the control steps it will
// simulate (an upper bound: every epoch runs to its full length, as it does once
// controllers avoid collisions) and the measured per-core rate of each controller's
// workload, hence core-hours.
#include <cstdint>
#include <string>
#include <vector>

#include "runtime/eval/experiment.hpp"

namespace esc::bench {

struct ControllerCost {
  std::string experiment;
  std::string controller;
  std::string architecture;
  double evaluations = 0.0;      // runs x generations x (lambda, or the GP population for a tree)
  double max_steps = 0.0;        // evaluations x epochs x steps
  double steps_per_second = 0.0; // measured on one core
  [[nodiscard]] double core_seconds() const noexcept { return max_steps / steps_per_second; }
};

// Measures each controller of each experiment for about `seconds_each` on one core; in
// experiment then controller order.
[[nodiscard]] std::vector<ControllerCost> estimate_campaign(const std::vector<eval::ExperimentSpec>& experiments,
                                                            double seconds_each);

// The campaign's wall time on `workers` workers (threads of all ranks), at most: every
// evaluation at full length and at its controller's one-core rate, scheduled as
// run_campaign schedules them (runs advancing together by eval::room_for_another_run,
// each round's pooled evaluations taken one at a time by the first free worker, a round
// ending with its longest worker), experiments one after the other. What it leaves out:
// evaluations that end early, and anything that makes a worker slower than one core alone
// (memory bandwidth, MPI messages), which only a measurement shows.
[[nodiscard]] double wall_seconds(const std::vector<eval::ExperimentSpec>& experiments,
                                  const std::vector<ControllerCost>& costs, std::size_t workers);

}  // namespace esc::bench
