#pragma once
// `esc export DIR... --table comparisons`: every comparison of best fitness that the end
// table and the report show (pair_rows.hpp): Welch's t test, the Mann-Whitney U test, the
// Vargha-Delaney A12, the ratio of the standard deviations and the Brown-Forsythe test of
// equal spread, each test's p adjusted by Holm over the table's family.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "runtime/report/comparisons.hpp"
#include "runtime/report/pair_rows.hpp"
#include "runtime/store/results_db.hpp"

namespace esc::report {

inline constexpr const char* kComparisonColumns =
    "study,experiment,condition_a,controller_a,condition_b,controller_b,welch_t,welch_df,welch_p,welch_p_holm,"
    "mann_whitney_u,mann_whitney_p,mann_whitney_exact,mann_whitney_p_holm,a12,sd_ratio,brown_forsythe_w,"
    "brown_forsythe_p,brown_forsythe_p_holm";

using ComparisonRow = PairRow<Comparison>;

[[nodiscard]] std::vector<ComparisonRow> comparison_rows(const std::vector<store::StoredDirectory>& directories);
// Header then rows: numbers with 17 significant digits, an undefined test's as `nan`,
// `mann_whitney_exact` 1 where U's p is from its exact distribution, else 0.
[[nodiscard]] std::string comparisons_csv(const std::vector<ComparisonRow>& rows);
// The same rows as objects keyed by the column names (NaN as null, `mann_whitney_exact` a boolean).
[[nodiscard]] nlohmann::ordered_json comparisons_json(const std::vector<ComparisonRow>& rows);

}  // namespace esc::report
