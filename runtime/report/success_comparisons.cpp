#include "runtime/report/success_comparisons.hpp"

#include <algorithm>
#include <cmath>

#include "runtime/report/comparisons.hpp"

namespace esc::report {

SuccessSample success_sample(std::span<const eval::RunResult> runs) {
  SuccessSample s;
  for (const eval::RunResult& r : runs) {
    s.evaluations.push_back(r.success_evaluation ? std::optional(static_cast<double>(*r.success_evaluation))
                                                 : std::nullopt);
    s.budget = std::max(s.budget, static_cast<double>(eval::evaluations_of(r.generations)));
  }
  return s;
}

std::vector<SuccessComparison> compare_success(std::span<const SuccessSample> samples,
                                               std::span<const std::pair<std::size_t, std::size_t>> pairs) {
  const auto successes = [](const SuccessSample& s) {
    return static_cast<std::size_t>(std::count_if(s.evaluations.begin(), s.evaluations.end(),
                                                  [](const auto& x) { return x.has_value(); }));
  };
  std::vector<SuccessComparison> out;
  std::vector<double> fisher_p, censored_p;
  for (const auto& [i, j] : pairs) {
    const SuccessSample& a = samples[i];
    const SuccessSample& b = samples[j];
    SuccessComparison c;
    c.a = i;
    c.b = j;
    c.successes_a = successes(a);
    c.runs_a = a.evaluations.size();
    c.successes_b = successes(b);
    c.runs_b = b.evaluations.size();
    // SciPy's p of 1 for a sample without runs would read as "no difference found".
    c.fisher = c.runs_a == 0 || c.runs_b == 0
                   ? FisherResult{std::nan(""), std::nan("")}
                   : fisher_exact(c.successes_a, c.runs_a - c.successes_a, c.successes_b, c.runs_b - c.successes_b);
    // One censoring point for both samples: runs of either that never succeeded tie there.
    // None when every run succeeded: runs ended at their success (`stop at success`) would
    // otherwise show a "budget" that is only the slowest success.
    const double budget = std::max(a.budget, b.budget);
    c.censored = censored_mann_whitney(a.evaluations, b.evaluations, budget);
    const bool censors = c.successes_a < c.runs_a || c.successes_b < c.runs_b;
    c.censored_at = censors ? budget + 1.0 : std::nan("");
    fisher_p.push_back(c.fisher.p_value);
    censored_p.push_back(c.censored.p_value);
    out.push_back(c);
  }
  const std::vector<double> fh = holm(fisher_p), ch = holm(censored_p);
  for (std::size_t k = 0; k < out.size(); ++k) {
    out[k].fisher_p_holm = fh[k];
    out[k].censored_p_holm = ch[k];
  }
  return out;
}

}  // namespace esc::report
