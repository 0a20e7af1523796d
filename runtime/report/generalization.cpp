#include "runtime/report/generalization.hpp"

#include <limits>

#include "runtime/report/statistics.hpp"

namespace esc::report {

namespace {

double mean_or_nan(const std::vector<double>& values) {
  return values.empty() ? std::numeric_limits<double>::quiet_NaN() : summarise(values).mean;
}

}  // namespace

std::optional<TransferSummary> summarise_transfers(const std::vector<eval::RunResult>& runs) {
  TransferSummary s;
  std::vector<double> origin, here, change, regained, best_here;
  double gained = 0.0;
  double lost = 0.0;
  for (const eval::RunResult& r : runs) {
    if (!r.transfer) continue;
    const eval::Transfer& t = *r.transfer;
    std::vector<double> best;
    for (const eval::GenerationStats& g : r.generations) best.push_back(g.best);
    const bool evolved = !t.evaluate_only && !r.generations.empty();
    const RunTransfer rt{r.run,
                         t.origin_run,
                         t.origin_fitness,
                         t.fitness_here,
                         eval::change_percent(t),
                         eval::regained_at(t, best),
                         evolved ? std::optional<double>(r.best_fitness) : std::nullopt,
                         evolved ? eval::loss_regained_percent(t, r.best_fitness) : std::nullopt};
    s.origin = t.experiment;
    s.evaluate_only = t.evaluate_only;
    origin.push_back(rt.origin_fitness);
    if (rt.fitness_here) here.push_back(*rt.fitness_here);
    if (rt.change_percent) change.push_back(*rt.change_percent);
    if (rt.regained_at) regained.push_back(*rt.regained_at);
    if (rt.best_here) best_here.push_back(*rt.best_here);
    if (rt.loss_regained) {
      gained += *rt.best_here - *rt.fitness_here;
      lost += rt.origin_fitness - *rt.fitness_here;
    }
    s.runs.push_back(rt);
  }
  if (s.runs.empty()) return std::nullopt;
  s.origin_mean = mean_or_nan(origin);
  s.here_mean = mean_or_nan(here);
  s.change_mean = mean_or_nan(change);
  s.regained = regained.size();
  s.regained_median = regained.empty() ? std::numeric_limits<double>::quiet_NaN() : summarise(regained).median;
  s.best_here_mean = mean_or_nan(best_here);
  s.loss_regained_pooled = lost > 0.0 ? 100.0 * gained / lost : std::numeric_limits<double>::quiet_NaN();
  return s;
}

}  // namespace esc::report
