#pragma once
// What an end term reads of every step, not only of the last: `mean(speed)`, `sum(x)`,
// `min(x)`, `max(x)`, `fraction(ir[0] > 0.5)` and `last(x)` fold a step expression over the
// steps of an epoch (or of the evaluation), and the sampled positions of a `positions(K)`
// descriptor are the value at one step. The evaluator feeds each aggregate every step's
// frame (after the step's physics, the frame the fitness's step term reads) and hands the
// folded value to the end term in a slot after the choice counts (docs/language.md,
// "Step aggregates").
#include <algorithm>
#include <cstdint>

#include "runtime/expr/program.hpp"

namespace esc::expr {

struct StepAggregate {
  // At: the value on the step sampled_step(sample, samples, T) (T: the steps an epoch may
  // run, or the evaluation's epochs x steps), or on the last step when the epoch (the
  // evaluation) ended before it. `last(x)` is sample 0 of 1: the last step.
  enum class Kind { Mean, Sum, Min, Max, Fraction, At };
  Kind kind = Kind::Mean;
  Program of;          // a step expression: what the fitness's `step:` may read
  int sample = 0;      // At only
  int samples = 1;
};

// Step (from 0) of sample i of k evenly spaced over steps 0 .. T - 1: round(i (T - 1) / (k - 1)),
// halves up, so the first sample is step 0 and the last step T - 1; one sample is step T - 1.
// Resolved from the experiment as it runs (eval::StepAggregates, made with its evaluator, after
// every `--set`), so `--set steps=N` moves the samples with the epoch.
[[nodiscard]] constexpr std::int64_t sampled_step(std::int64_t i, std::int64_t k, std::int64_t steps) noexcept {
  if (k <= 1) return steps - 1;
  return (2 * i * (steps - 1) + (k - 1)) / (2 * (k - 1));
}

// One aggregate's value so far. Sums saturate at +-kSaturation as a fitness does, so a mean
// or a sum is always finite; over no step every aggregate is 0 (as `x / 0` is).
class StepAccumulator {
 public:
  // `at` is the step an At aggregate reads (sampled_step), `step` the one just taken.
  void add(const StepAggregate& a, double v, std::int64_t step, std::int64_t at) noexcept {
    using K = StepAggregate::Kind;
    switch (a.kind) {
      case K::Mean:
      case K::Sum: value_ = saturating_add(value_, v); break;
      case K::Min: value_ = seen_ == 0 ? v : std::min(value_, v); break;
      case K::Max: value_ = seen_ == 0 ? v : std::max(value_, v); break;
      case K::Fraction: value_ += v != 0.0 ? 1.0 : 0.0; break;
      case K::At: if (step <= at) value_ = v; break;
    }
    ++seen_;
  }
  // The aggregate over the steps added since the last reset.
  [[nodiscard]] double value(const StepAggregate& a) const noexcept {
    using K = StepAggregate::Kind;
    if (seen_ == 0) return 0.0;
    if (a.kind == K::Mean || a.kind == K::Fraction) return value_ / static_cast<double>(seen_);
    return value_;
  }
  void reset() noexcept { value_ = 0.0; seen_ = 0; }

 private:
  double value_ = 0.0;
  std::int64_t seen_ = 0;
};

}  // namespace esc::expr
