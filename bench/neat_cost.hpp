#pragma once
// What NEAT itself costs beside the evaluations it serves (`esc bench`, issue 43): one
// core runs a NEAT controller's first generations as a run does, and the thread CPU time is
// split three ways: NEAT's own work (ask: breeding, speciation, each child encoded; tell:
// taking the scores, novelty's archive when it scores by novelty), building each
// candidate's network from its genome (decoding it into a Controller, as every evaluation
// does first), and the evaluations (the simulation, the network's steps, the fitness),
// net of that building.
#include <cstdint>

#include "runtime/control/controller_spec.hpp"
#include "runtime/eval/experiment.hpp"

namespace esc::bench {

struct NeatCost {
  int generations = 0;
  std::int64_t evaluations = 0;
  double neat_s = 0.0;        // ask and tell
  double build_s = 0.0;       // a Controller built from each genome
  double evaluate_s = 0.0;    // the evaluations, their own building taken out
  double hidden_nodes = 0.0;  // NEAT's metrics: means over the last generation's networks
  double enabled_links = 0.0;
  // NEAT's work and the network building against the evaluations'.
  [[nodiscard]] double fraction() const { return (neat_s + build_s) / evaluate_s; }
};

// Runs `generations` generations of `controller`'s algorithm (its experiment's settings for
// it, seed 1) and times them. Throws std::invalid_argument when the controller is not a
// `neat(...)` network.
[[nodiscard]] NeatCost measure_neat_cost(const eval::ExperimentSpec& experiment,
                                         const control::ControllerSpec& controller, int generations);

}  // namespace esc::bench
