#pragma once
// The step aggregates of an experiment's end terms (the fitness's and further objectives'
// `epoch:` and `evaluation:` terms, the descriptors), folded step by step during one
// evaluation: those of an epoch's terms restart at every epoch, those of the evaluation's
// at its start. An experiment without any costs one empty check per step.
#include <cstdint>
#include <span>
#include <vector>

#include "runtime/eval/experiment.hpp"
#include "runtime/expr/step_aggregate.hpp"

namespace esc::eval {

class StepAggregates {
 public:
  explicit StepAggregates(const ExperimentSpec& spec);

  [[nodiscard]] bool empty() const noexcept { return terms_.empty(); }
  // The most aggregates one end term reads: the slots its frame needs after the counts.
  [[nodiscard]] std::size_t widest() const noexcept { return widest_; }

  void begin_evaluation() noexcept;
  void begin_epoch() noexcept;
  // Folds in the frame of a step just taken: `epoch_step` and `evaluation_step` count from 0.
  void step(std::span<const double> frame, std::int64_t epoch_step, std::int64_t evaluation_step) noexcept;
  // The values of the aggregates `list` (one of the spec's lists) into `out`, in order.
  void write(const std::vector<expr::StepAggregate>& list, std::span<double> out) const noexcept;

 private:
  struct Term {
    const std::vector<expr::StepAggregate>* list;
    bool per_epoch;
    std::vector<expr::StepAccumulator> values;
    std::vector<std::int64_t> at;   // the step each At aggregate reads (expr::sampled_step)
  };
  std::vector<Term> terms_;
  std::size_t widest_ = 0;
};

}  // namespace esc::eval
