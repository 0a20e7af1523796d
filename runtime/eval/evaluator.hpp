#pragma once
// Evaluates one genome of one controller: `epochs` epochs from start poses drawn from the
// evaluation's own random stream, each at most `steps` control steps of
//   sense (IR) -> control -> act + physics -> observe -> fitness term -> stop conditions.
// An Evaluator owns one simulated world and reuses it for every evaluation it runs, so a
// worker thread keeps one Evaluator for a whole campaign.
#include <cstdint>
#include <span>

#include "runtime/eval/experiment.hpp"
#include "runtime/sim/world.hpp"

namespace esc::eval {

struct Evaluation {
  double fitness = 0.0;
  std::int64_t steps = 0;   // control steps simulated (epochs may end early)
};

class Evaluator {
 public:
  // `spec` must outlive the evaluator.
  explicit Evaluator(const ExperimentSpec& spec);

  // Deterministic in (controller, genome, seed) whatever this evaluator ran before.
  [[nodiscard]] Evaluation evaluate(const control::ControllerSpec& controller,
                                    std::span<const double> genome, std::uint64_t seed);

 private:
  const ExperimentSpec* spec_;
  sim::World world_;
};

}  // namespace esc::eval
