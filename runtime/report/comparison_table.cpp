#include "runtime/report/comparison_table.hpp"

#include <fmt/format.h>

namespace esc::report {

std::vector<ComparisonRow> comparison_rows(const std::vector<store::StoredDirectory>& directories) {
  return pair_rows<Comparison>(
      directories, [](const StudyTable& t) -> const auto& { return t.comparisons; }, experiment_comparisons);
}

std::string comparisons_csv(const std::vector<ComparisonRow>& rows) {
  return pair_table_csv(rows, kComparisonColumns, [](const Comparison& c) {
    return fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{}", number_text(c.welch.statistic),
                       number_text(c.welch.df), number_text(c.welch.p_value), number_text(c.welch_p_holm),
                       number_text(c.mann_whitney.statistic), number_text(c.mann_whitney.p_value),
                       c.mann_whitney.exact ? 1 : 0, number_text(c.mann_whitney_p_holm), number_text(c.a12),
                       number_text(c.sd_ratio), number_text(c.spread.statistic), number_text(c.spread.p_value),
                       number_text(c.spread_p_holm));
  });
}

nlohmann::ordered_json comparisons_json(const std::vector<ComparisonRow>& rows) {
  return pair_table_json(rows, [](const Comparison& c) {
    return nlohmann::ordered_json{{"welch_t", number_json(c.welch.statistic)},
                                  {"welch_df", number_json(c.welch.df)},
                                  {"welch_p", number_json(c.welch.p_value)},
                                  {"welch_p_holm", number_json(c.welch_p_holm)},
                                  {"mann_whitney_u", number_json(c.mann_whitney.statistic)},
                                  {"mann_whitney_p", number_json(c.mann_whitney.p_value)},
                                  {"mann_whitney_exact", c.mann_whitney.exact},
                                  {"mann_whitney_p_holm", number_json(c.mann_whitney_p_holm)},
                                  {"a12", number_json(c.a12)},
                                  {"sd_ratio", number_json(c.sd_ratio)},
                                  {"brown_forsythe_w", number_json(c.spread.statistic)},
                                  {"brown_forsythe_p", number_json(c.spread.p_value)},
                                  {"brown_forsythe_p_holm", number_json(c.spread_p_holm)}};
  });
}

}  // namespace esc::report
