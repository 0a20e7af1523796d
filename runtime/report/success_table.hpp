#pragma once
// `esc export DIR... --table success`: every comparison of success that the end table and
// the report show (pair_rows.hpp), Fisher's exact test and the censored Mann-Whitney test.
// Directories whose experiments declare no `success when` have no rows.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "runtime/report/pair_rows.hpp"
#include "runtime/report/success_comparisons.hpp"
#include "runtime/store/results_db.hpp"

namespace esc::report {

inline constexpr const char* kSuccessColumns =
    "study,experiment,condition_a,controller_a,condition_b,controller_b,successes_a,runs_a,successes_b,runs_b,"
    "fisher_p,fisher_p_holm,odds_ratio,censored_u,censored_p,censored_p_holm,censored_at";

using SuccessRow = PairRow<SuccessComparison>;

// A plain experiment's comparisons: every pair of its controllers, one family per test; none
// without a success test.
[[nodiscard]] std::vector<SuccessComparison> experiment_success(const store::StoredExperiment& e);

[[nodiscard]] std::vector<SuccessRow> success_rows(const std::vector<store::StoredDirectory>& directories);
// Header then rows: p values and the odds ratio with 17 significant digits, NaN as `nan`,
// an infinite odds ratio (every run of the second failed, one of the first succeeded) `inf`,
// `censored_at` `nan` when every run of the pair succeeded.
[[nodiscard]] std::string success_csv(const std::vector<SuccessRow>& rows);
// The same rows as objects keyed by the column names (NaN as null, infinity as "inf").
[[nodiscard]] nlohmann::ordered_json success_json(const std::vector<SuccessRow>& rows);

}  // namespace esc::report
