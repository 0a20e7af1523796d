#pragma once
// summary.json: the machine-readable result of a campaign.
// {"experiment": name, "seed": master seed, "controllers": {NAME: {"architecture": "8-14-6",
//   "genome_size": 216, "runs": [{"run": 1, "seed": ..., "best_fitness": ...,
//   "best": [per generation], "mean": [per generation] (the population's sd is in esc.db and
//   its exports: summary.json keeps what the command-line contract reads),
//   "best_tree": script code (tree controllers only),
//   "behavior_usage": {BEHAVIOR: steps in the run's best evaluation} (symbolic heads, supervisors),
//   "usage": {"behaviors": [names], "best_steps": [[per behavior] per generation],
//             "mean_steps": [[...] per generation], "steps_total": [per generation]},
//   "transfer": {"experiment", "origin_run", "origin_fitness", "fitness_here", "change_percent",
//                "regained_at_generation" (start from only)} (runs that start from a stored genome),
//   "success_evaluation": the run's evaluations up to its first success, or null}],
//   "success": {"successes", "runs", "median_evaluations" (over the runs that succeeded, or
//               null)}}}}
// "success" (the test, SuccessSpec::text) and the two success entries only when the experiment
// declares `success when`.
// Runs are numbered from 1 (as in file names, the console and the report); the per-generation
// arrays start at generation 0, the initial population.
// A study's: {"study": name, "seed": master seed, "conditions": [{"name": ..., "experiment":
//   ..., "settings": {KEY: VALUE as written}, "success" (when declared), "controllers": {as above}}]}.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "runtime/eval/campaign.hpp"
#include "runtime/eval/study.hpp"

namespace esc::store {

[[nodiscard]] nlohmann::ordered_json summary_json(const eval::CampaignResult& result);

// One condition of a study's summary: its results so far (`result.experiment` is its
// experiment's name).
struct ConditionSummary {
  std::string name;
  std::vector<eval::ConditionSetting> settings;
  eval::CampaignResult result;
};

[[nodiscard]] nlohmann::ordered_json study_summary_json(const std::string& study, std::uint64_t seed,
                                                        const std::vector<ConditionSummary>& conditions);

// summary.json's text: nlohmann's two-space layout, except that an array of numbers stays on
// one line. One number per line made a full-length study's summary.json 10.6 MB, 45 % of it
// indentation (the committed hard maze study's); the values are written as dump() writes them.
[[nodiscard]] std::string summary_text(const nlohmann::ordered_json& summary);

}  // namespace esc::store
