#pragma once
// A run while it goes: the statistics of each finished generation, and everything needed to
// continue it after the last one. What an algorithm continues from is its own, saved by its
// optimizer (runtime/evo/optimizer.hpp) as bytes the run loop and the store do not read.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "runtime/eval/transfer.hpp"
#include "runtime/evo/optimizer.hpp"

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
  std::vector<evo::Metric> metrics{};   // the optimizer's own (evo::Optimizer::metrics)
};

// An optimizer's state after a run's last finished generation: the algorithm that saved it
// (evo::Algorithm::name, or evo::kEvaluateOnly), the layout of its bytes, and the bytes.
struct OptimizerState {
  std::string algorithm;
  std::uint32_t format = 0;
  evo::StateBytes bytes;
  friend bool operator==(const OptimizerState&, const OptimizerState&) = default;
};

// What a run's optimizer keeps beside its best (evo::Optimizer::members), as the store names
// it: the values each member holds (objectives, fitness first, then descriptors) and, for an
// archive, its cells. The same for every run of a controller.
struct MemberLayout {
  evo::MemberKind kind = evo::MemberKind::Front;
  std::vector<std::string> objectives;    // names, in the experiment's order
  std::vector<bool> minimized;            // per objective
  std::vector<std::string> descriptors;
  std::vector<evo::Bounds> descriptor_ranges;
  std::vector<std::size_t> bins;          // as evo::Members holds them
  std::vector<double> centroids;
  friend bool operator==(const MemberLayout&, const MemberLayout&) = default;
};

// Everything needed to continue a run after its last finished generation: restarting
// generation `generations.size()` from `optimizer` reproduces the uninterrupted run bit for
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
  OptimizerState optimizer;
  std::optional<Transfer> transfer{};         // set when the run starts from a stored genome
  // `success when ...`: the evaluations of the run up to and including the first that
  // succeeded (generation by generation, candidates in ask order, counted from 1); none
  // while none has, and always when the experiment declares no test.
  std::optional<std::int64_t> success_evaluation{};
  // What the optimizer keeps beside the best, for optimizers that keep something: its layout,
  // and the last finished generation's members (a front whole, an archive's changed cells),
  // objectives as measured (a minimised one not negated), when that generation stores them
  // (`members_due`: every generation of an archive; a front's at the multiples of the
  // experiment's members_every and at the run's last). Stored with that generation, never
  // read back: nothing continues from them.
  std::shared_ptr<const MemberLayout> member_layout{};
  std::vector<evo::Member> members{};
  bool members_due = false;
};

// The evaluations a run has finished: those of its generations so far.
[[nodiscard]] inline std::int64_t evaluations_of(const std::vector<GenerationStats>& generations) noexcept {
  std::int64_t n = 0;
  for (const GenerationStats& g : generations) n += g.evaluations;
  return n;
}

}  // namespace esc::eval
