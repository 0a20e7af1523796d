#pragma once
// The `esc bench` workloads, registered with Google Benchmark at run time because they
// need a compiled experiment: the paper's obstacle-avoidance evaluation (IR, physics,
// network, fitness) on one core, and a generation's evaluations on 1..N threads.
#include <vector>

#include "runtime/eval/experiment.hpp"

namespace esc::bench {

struct Workload {
  const eval::ExperimentSpec* experiment;
  const control::ControllerSpec* controller;
};

// Registers "step/<experiment>/<controller>" (counter steps/s, one thread) and
// "threads/<experiment>/<controller>/T" for T in `thread_counts` (counters evals/s, steps/s).
void register_workload(const Workload& w, const std::vector<int>& thread_counts);

}  // namespace esc::bench
