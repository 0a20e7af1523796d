#pragma once
// `esc export DIR... --table metrics`: what each run's optimizer reported about itself after
// every generation (CMA-ES's step size and condition number, ...), as one tidy table (a row
// per experiment, condition, controller, run, generation and metric), ready for R or pandas.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "runtime/store/results_db.hpp"

namespace esc::store {

// The columns, in order: `condition` is a study's condition and empty for a plain
// experiment; `algorithm` what evolved the controller.
inline constexpr const char* kMetricsColumns = "experiment,condition,controller,algorithm,run,generation,metric,value";

// Header then rows (runs from 1, generations from 0; values with 17 significant digits, NaN
// as `nan`), finished runs and runs in progress; algorithms that report nothing have none.
[[nodiscard]] std::string metrics_csv(const std::vector<StoredDirectory>& directories);
// The same rows as an array of objects keyed by the column names (NaN as null).
[[nodiscard]] nlohmann::ordered_json metrics_json(const std::vector<StoredDirectory>& directories);

}  // namespace esc::store
