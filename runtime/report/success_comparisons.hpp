#pragma once
// Comparisons of success, for experiments that declare `success when`: per pair of samples
// of runs, Fisher's exact test of the success counts and the censored Mann-Whitney (Gehan)
// test of the evaluations to success (statistics.hpp), each adjusted by Holm's method over
// the family of pairs it is given, as comparisons.hpp adjusts the tests of the fitness.
// Novelty search, MAP-Elites and fitness-based search optimise different things; whether and
// how soon each run solved the task is what they share.
#include <cstddef>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "runtime/eval/campaign.hpp"
#include "runtime/report/statistics.hpp"

namespace esc::report {

// A sample of runs as the success tests read it.
struct SuccessSample {
  // Per run: the evaluations up to and including its first success; none when it never
  // succeeded (censored).
  std::vector<std::optional<double>> evaluations;
  double budget = 0.0;   // the most evaluations any of its runs made
};
[[nodiscard]] SuccessSample success_sample(std::span<const eval::RunResult> runs);

struct SuccessComparison {
  std::size_t a = 0, b = 0;   // indices of the samples compared
  std::size_t successes_a = 0, runs_a = 0, successes_b = 0, runs_b = 0;
  FisherResult fisher;
  TestResult censored;        // censored_mann_whitney of the evaluations to success
  // What a run that never succeeded counts as: the larger budget + 1; NaN when every run of
  // both succeeded (nothing is censored).
  double censored_at = 0.0;
  double fisher_p_holm = 0.0;
  double censored_p_holm = 0.0;
};

// One comparison per pair (in the order given); each test adjusted as one family.
[[nodiscard]] std::vector<SuccessComparison> compare_success(
    std::span<const SuccessSample> samples, std::span<const std::pair<std::size_t, std::size_t>> pairs);

// How the end table and the report state the censoring, under the comparisons.
inline constexpr const char* kCensoringNote =
    "a run that never succeeded counts as more than the budget (every such run tied above every success: "
    "Gehan's test, the Mann-Whitney U test of censored values)";

}  // namespace esc::report
