#include "runtime/eval/success.hpp"

#include <algorithm>
#include <limits>
#include <vector>

namespace esc::eval {

double tested_value(const ExperimentSpec& spec, const SuccessSpec& test, const evo::Outcome& outcome) {
  const std::span<const double> values =
      test.of == SuccessSpec::Of::Objective ? std::span<const double>(outcome.objectives) : outcome.descriptors;
  // An outcome without the value (none is made so) fails every test.
  if (test.index >= values.size()) return std::numeric_limits<double>::quiet_NaN();
  return test.of == SuccessSpec::Of::Objective ? spec.as_declared(test.index, values[test.index])
                                               : values[test.index];
}

std::optional<std::size_t> first_success(const ExperimentSpec& spec, std::span<const evo::Outcome> outcomes) {
  if (!spec.success) return std::nullopt;
  for (std::size_t i = 0; i < outcomes.size(); ++i)
    if (spec.success->passes(tested_value(spec, *spec.success, outcomes[i]))) return i;
  return std::nullopt;
}

SuccessCount count_successes(std::span<const RunResult> runs) {
  std::vector<std::optional<double>> evaluations;
  for (const RunResult& r : runs)
    evaluations.push_back(r.success_evaluation ? std::optional(static_cast<double>(*r.success_evaluation))
                                               : std::nullopt);
  return count_successes(evaluations);
}

SuccessCount count_successes(std::span<const std::optional<double>> runs) {
  SuccessCount c;
  c.runs = runs.size();
  std::vector<double> evaluations;
  for (const std::optional<double>& r : runs)
    if (r) evaluations.push_back(*r);
  c.successes = evaluations.size();
  std::sort(evaluations.begin(), evaluations.end());
  const std::size_t n = evaluations.size();
  c.median_evaluations = n == 0       ? std::numeric_limits<double>::quiet_NaN()
                         : n % 2 == 1 ? evaluations[n / 2]
                                      : 0.5 * (evaluations[n / 2 - 1] + evaluations[n / 2]);
  return c;
}

}  // namespace esc::eval
