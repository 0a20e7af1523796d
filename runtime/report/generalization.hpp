#pragma once
// The paper's generalization figures, per controller of an experiment that evaluates or
// starts from another's controllers: the fitness each run's genome had in the origin
// experiment, its fitness here, the change in percent ("lose around 10% of their
// fitness"), and for `start from` the generation at which each run regained the origin's
// level ("reach the same level again in 150 generations", "never recover"), its best here
// and the share of its loss it made up ("only recover half of it"). The end table of
// `esc run` and the report show them.
#include <optional>
#include <string>
#include <vector>

#include "runtime/eval/campaign.hpp"

namespace esc::report {

struct RunTransfer {
  int run = 0;                          // from 0
  int origin_run = 0;                   // from 0
  double origin_fitness = 0.0;
  std::optional<double> fitness_here;
  std::optional<double> change_percent;
  std::optional<int> regained_at;       // generation; none when never (or only evaluated)
  std::optional<double> best_here;      // start from: the run's best over its generations here
  std::optional<double> loss_regained;  // start from: eval::loss_regained_percent
};

struct TransferSummary {
  std::string origin;                   // the origin experiment
  bool evaluate_only = false;
  std::vector<RunTransfer> runs;        // the runs that hold a transfer, in run order
  // Means over those runs (NaN when none has the value).
  double origin_mean = 0.0;
  double here_mean = 0.0;
  double change_mean = 0.0;             // mean of the runs' changes, in percent
  std::size_t regained = 0;             // runs that regained the origin's level
  double regained_median = 0.0;         // their median generation (NaN when none)
  double best_here_mean = 0.0;          // start from (NaN otherwise)
  // Over the runs that lost something: their gains summed over their losses summed, in
  // percent (NaN when none lost). Pooled, not a mean of ratios: a run that lost next to
  // nothing would weigh as much as one that lost half.
  double loss_regained_pooled = 0.0;
};

// Nothing when no run of `runs` started from a stored genome.
[[nodiscard]] std::optional<TransferSummary> summarise_transfers(const std::vector<eval::RunResult>& runs);

}  // namespace esc::report
