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

// Measures each controller of each experiment for about `seconds_each` on one core.
[[nodiscard]] std::vector<ControllerCost> estimate_campaign(const std::vector<eval::ExperimentSpec>& experiments,
                                                            double seconds_each);

}  // namespace esc::bench
