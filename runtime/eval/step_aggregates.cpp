#include "runtime/eval/step_aggregates.hpp"

#include <algorithm>
#include <utility>

namespace esc::eval {

StepAggregates::StepAggregates(const ExperimentSpec& spec) {
  const auto add = [&](const std::vector<expr::StepAggregate>& list, bool per_epoch) {
    if (list.empty()) return;
    const std::int64_t steps = per_epoch ? spec.steps : std::int64_t{spec.epochs} * spec.steps;
    std::vector<std::int64_t> at;
    for (const expr::StepAggregate& a : list) at.push_back(expr::sampled_step(a.sample, a.samples, steps));
    terms_.push_back({&list, per_epoch, std::vector<expr::StepAccumulator>(list.size()), std::move(at)});
    widest_ = std::max(widest_, list.size());
  };
  std::vector<const FitnessSpec*> fitnesses{&spec.fitness};
  for (const FitnessSpec& f : spec.further) fitnesses.push_back(&f);
  for (const FitnessSpec* f : fitnesses) {
    add(f->epoch_aggregates, true);
    add(f->evaluation_aggregates, false);
  }
  for (const DescriptorSpec& d : spec.descriptors) add(d.aggregates, !d.at_evaluation);
}

void StepAggregates::begin_evaluation() noexcept {
  for (Term& t : terms_)
    for (expr::StepAccumulator& v : t.values) v.reset();
}

void StepAggregates::begin_epoch() noexcept {
  for (Term& t : terms_)
    if (t.per_epoch)
      for (expr::StepAccumulator& v : t.values) v.reset();
}

void StepAggregates::step(std::span<const double> frame, std::int64_t epoch_step,
                          std::int64_t evaluation_step) noexcept {
  for (Term& t : terms_) {
    const std::int64_t step = t.per_epoch ? epoch_step : evaluation_step;
    for (std::size_t k = 0; k < t.values.size(); ++k) {
      const expr::StepAggregate& a = (*t.list)[k];
      t.values[k].add(a, a.of.eval(frame), step, t.at[k]);
    }
  }
}

void StepAggregates::write(const std::vector<expr::StepAggregate>& list, std::span<double> out) const noexcept {
  for (const Term& t : terms_) {
    if (t.list != &list) continue;
    for (std::size_t k = 0; k < t.values.size() && k < out.size(); ++k) out[k] = t.values[k].value(list[k]);
    return;
  }
}

}  // namespace esc::eval
