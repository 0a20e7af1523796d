#include "runtime/report/stored_study.hpp"

#include <algorithm>

namespace esc::report {

std::vector<const store::StoredExperiment*> conditions_in_order(const store::StoredDirectory& d) {
  std::vector<const store::StoredExperiment*> conditions;
  for (const store::StoredExperiment& e : d.experiments)
    if (e.condition) conditions.push_back(&e);
  std::stable_sort(conditions.begin(), conditions.end(),
                   [](const auto* a, const auto* b) { return a->condition->index < b->condition->index; });
  return conditions;
}

namespace {

// The best fitness of each of the controller's finished runs.
std::vector<double> runs_best(const store::StoredController& c) {
  std::vector<double> best;
  for (const auto& r : c.finished) best.push_back(r.best_fitness);
  return best;
}

}  // namespace

ConditionSamples condition_samples(const store::StoredExperiment& condition) {
  ConditionSamples s{condition.condition ? condition.condition->name : condition.name, {}};
  const bool declares_success = condition.settings.count("success") != 0;
  for (const store::StoredController& c : condition.controllers) {
    s.controllers.emplace_back(c.name, runs_best(c));
    if (declares_success) s.success.push_back(success_sample(c.finished));
  }
  return s;
}

std::vector<Comparison> experiment_comparisons(const store::StoredExperiment& e) {
  std::vector<std::vector<double>> best;
  for (const store::StoredController& c : e.controllers) best.push_back(runs_best(c));
  return compare(best, all_pairs(best.size()));
}

}  // namespace esc::report
