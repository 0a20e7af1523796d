#pragma once
// summary.json: the machine-readable result of a campaign.
// {"experiment": name, "seed": master seed, "controllers": {NAME: {"architecture": "8-14-6",
//   "genome_size": 216, "runs": [{"run": 1, "seed": ..., "best_fitness": ...,
//   "best": [per generation], "mean": [per generation], "sd": [per generation],
//   "best_tree": script code (tree controllers only)}]}}}
// Runs are numbered from 1 (as in file names, the console and the report); the per-generation
// arrays start at generation 0, the initial population.
#include <nlohmann/json.hpp>

#include "runtime/eval/campaign.hpp"

namespace esc::store {

[[nodiscard]] nlohmann::ordered_json summary_json(const eval::CampaignResult& result);

}  // namespace esc::store
