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
  // The measured evaluations' lengths, in seconds on one core (random genomes: epochs end
  // at collisions or an empty accumulator, so lengths vary as in early generations).
  std::vector<double> evaluation_seconds;
  [[nodiscard]] double core_seconds() const noexcept { return max_steps / steps_per_second; }
};

// Measures each controller of each experiment for about `seconds_each` on one core; in
// experiment then controller order.
[[nodiscard]] std::vector<ControllerCost> estimate_campaign(const std::vector<eval::ExperimentSpec>& experiments,
                                                            double seconds_each);

// The campaign scheduled on `workers` workers (threads of all ranks) as run_campaign
// schedules it: runs advancing together by eval::room_for_another_run, each round's pooled
// evaluations taken one at a time by the first free worker, a round ending with its
// longest worker, experiments one after the other. Every worker runs at the one-core
// rate: memory bandwidth and MPI messages are not in it (only a measurement shows them).
struct Schedule {
  double wall_seconds = 0.0;
  double work_seconds = 0.0;   // the evaluations' total length
  [[nodiscard]] double efficiency(std::size_t workers) const noexcept {
    return work_seconds / (static_cast<double>(workers) * wall_seconds);
  }
};

enum class Lengths {
  Full,       // every evaluation at full length: the campaign's wall time at most
  Measured,   // lengths drawn in turn from ControllerCost::evaluation_seconds: how much
              // evaluations that end early cost in idle workers
};

[[nodiscard]] Schedule schedule(const std::vector<eval::ExperimentSpec>& experiments,
                                const std::vector<ControllerCost>& costs, std::size_t workers, Lengths lengths);

}  // namespace esc::bench
