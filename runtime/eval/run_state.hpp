#pragma once
// A run while it goes: the statistics of each finished generation, and everything needed to
// continue it after the last one. What an algorithm continues from is its own: the ES its
// parents with their step sizes, GP its last evaluated population, one alternative each of
// RunState::algorithm, so that nothing tells them apart by emptiness (the store keeps each
// in a table of its own: runtime/store/es_state.*, tree_state.*).
#include <cstdint>
#include <optional>
#include <variant>
#include <vector>

#include "runtime/eval/transfer.hpp"
#include "runtime/evo/es.hpp"
#include "runtime/evo/gp/selection.hpp"

namespace esc::eval {

// The steps each action (symbolic head) or behavior (supervisor) acted in one generation:
// in its best evaluation (the first of the generation's best fitness) and on average over
// all its evaluations. Empty for a classical head.
struct GenerationUsage {
  std::int64_t steps_total = 0;     // control steps of the best evaluation
  std::vector<std::int64_t> best;   // per choice, in ControllerSpec::choice_names() order
  std::vector<double> mean;         // per choice

  [[nodiscard]] bool empty() const noexcept { return best.empty(); }
  friend bool operator==(const GenerationUsage&, const GenerationUsage&) = default;
};

struct GenerationStats {
  int generation = 0;          // from 0
  double best = 0.0;           // best fitness among this generation's evaluated offspring
  double mean = 0.0;
  double sd = 0.0;
  std::int64_t evaluations = 0;
  std::int64_t steps = 0;      // control steps simulated in this generation
  // Wall time of the round that evaluated this generation, shared with the runs that
  // advanced with it (not part of the result proper).
  double seconds = 0.0;
  GenerationUsage usage{};
  // Evaluations whose fitness reached the saturation limit, +-expr::kSaturation (beyond it,
  // or NaN, which counts as the lowest): fitness terms that overflow.
  std::int64_t saturated = 0;
};

// What the ES breeds the next generation from: the mu parents selected after the last
// generation (genes, step sizes and fitness).
struct EsState {
  std::vector<evo::Individual> parents;
};

// What GP breeds the next generation from: the last generation evaluated, each tree with its
// fitness; empty before generation 0.
struct GpState {
  std::vector<evo::gp::Individual> population;
};

// Everything needed to continue a run after its last finished generation: restarting
// generation `generations.size()` from `algorithm` reproduces the uninterrupted run bit for
// bit, because every random stream is derived from (run seed, generation, individual).
struct RunState {
  int run = 0;
  std::uint64_t seed = 0;
  std::vector<GenerationStats> generations;   // finished so far
  bool has_best = false;
  double best_fitness = 0.0;
  std::vector<double> best_genome;            // as RunResult::best_genome
  int best_generation = 0;
  int best_index = 0;
  std::variant<EsState, GpState> algorithm;   // networks by the ES, trees by GP
  std::optional<Transfer> transfer{};         // set when the run starts from a stored genome
};

}  // namespace esc::eval
