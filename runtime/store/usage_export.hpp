#pragma once
// `esc export DIR... --table usage`: how often each action or behavior acted, per run and
// generation, as one tidy table (a row per experiment, condition, controller, run, generation
// and behavior), ready for R or pandas to draw the paper's Figure 2 again.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "runtime/store/results_db.hpp"

namespace esc::store {

// The columns, in order: `condition` is a study's condition and empty for a plain
// experiment; then the steps the behavior acted in the generation's best evaluation, their
// mean over all the generation's evaluations, and the best evaluation's steps; last the
// behavior's library ("" for an action) and whether it is marked `useless` (1) or not (0),
// as the report groups them.
inline constexpr const char* kUsageColumns =
    "experiment,condition,controller,run,generation,behavior,best_steps,mean_steps,steps_total,library,useless";

// Header then rows (runs from 1, generations from 0; mean_steps with 17 significant digits),
// finished runs and runs in progress; controllers without actions or behaviors have none.
[[nodiscard]] std::string usage_csv(const std::vector<StoredDirectory>& directories);
// The same rows as an array of objects keyed by the column names.
[[nodiscard]] nlohmann::ordered_json usage_json(const std::vector<StoredDirectory>& directories);

}  // namespace esc::store
