#pragma once
// Every evaluation of a stored run, measured again. A run stores its generations'
// statistics, its best and its optimizer's state, not each evaluation (a maze run makes
// 250,000): made again from its seed, with the experiment it ran (experiment_of_run), it is
// the same run, since every random stream derives from the run seed, and that is checked:
// each generation's statistics must equal the stored ones, or the re-run is refused.
// `esc replay --evaluations` writes what this returns; Lehman & Stanley's picture of where
// every evaluated robot ends (their figure 4) is drawn from it.
#include <cstddef>
#include <string>
#include <vector>

#include "app/stored_run.hpp"
#include "runtime/eval/campaign.hpp"

namespace esc::app {

struct RunEvaluations {
  std::vector<std::string> objectives;    // the fitness's name, then the further objectives'
  std::vector<std::string> descriptors;
  std::vector<eval::DeclaredRange> descriptor_ranges;
  std::vector<int> generation;            // per evaluation, from 0
  std::vector<int> candidate;             // per evaluation, its place in its generation
  // Per evaluation, width() values: each objective as the script declares it (a minimised
  // one not negated), then each descriptor.
  std::vector<double> values;

  [[nodiscard]] std::size_t width() const noexcept { return objectives.size() + descriptors.size(); }
  [[nodiscard]] std::size_t size() const noexcept { return generation.size(); }
};

// Run `run` (from 0) of `controller`, made again on `threads` threads (0: all) in `ran`, the
// experiment the stored run ran (experiment_of_run); `progress`, if any, hears the re-run's
// events. Throws Error (ErrorKind::Results) when the run is not finished or the re-run
// differs from the stored run (naming the first generation that does).
[[nodiscard]] RunEvaluations run_evaluations(const StoredRun& stored, const eval::ExperimentSpec& ran,
                                             const std::string& controller, int run, int threads,
                                             eval::CampaignListener* progress = nullptr);

}  // namespace esc::app
