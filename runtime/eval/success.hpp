#pragma once
// Which evaluation of a run first met the experiment's `success when` test, and how a
// controller's runs fared. The run loop (run_job.cpp) asks after every generation, from what
// the generation's candidates measured as optimizers are told it (evo::Outcome: a minimised
// objective negated), and keeps the answer in the run's state, so a resumed run continues
// the count where it stopped. summary.json, the end table and the report count the runs.
#include <cstddef>
#include <optional>
#include <span>

#include "runtime/eval/campaign.hpp"
#include "runtime/eval/experiment.hpp"
#include "runtime/evo/optimizer.hpp"

namespace esc::eval {

// The value `test` reads in `outcome`, as the script declares it: a minimised objective's
// own value (the outcome holds its negation), a descriptor's reduced value.
[[nodiscard]] double tested_value(const ExperimentSpec& spec, const SuccessSpec& test, const evo::Outcome& outcome);

// The index of the first outcome, in candidate (ask) order, that passes the experiment's
// test; none when no outcome does or the experiment declares no test.
[[nodiscard]] std::optional<std::size_t> first_success(const ExperimentSpec& spec,
                                                       std::span<const evo::Outcome> outcomes);

// A controller's runs as success counts them.
struct SuccessCount {
  std::size_t successes = 0;
  std::size_t runs = 0;
  double median_evaluations = 0.0;   // over the runs that succeeded; NaN when none did
};
[[nodiscard]] SuccessCount count_successes(std::span<const RunResult> runs);
// The same from each run's evaluations to success (none: it never succeeded).
[[nodiscard]] SuccessCount count_successes(std::span<const std::optional<double>> evaluations);

}  // namespace esc::eval
