#include "runtime/report/success_table.hpp"

#include <fmt/format.h>

#include "runtime/report/comparisons.hpp"

namespace esc::report {

std::vector<SuccessComparison> experiment_success(const store::StoredExperiment& e) {
  if (e.settings.count("success") == 0) return {};
  std::vector<SuccessSample> samples;
  for (const store::StoredController& c : e.controllers) samples.push_back(success_sample(c.finished));
  return compare_success(samples, all_pairs(samples.size()));
}

std::vector<SuccessRow> success_rows(const std::vector<store::StoredDirectory>& directories) {
  return pair_rows<SuccessComparison>(
      directories, [](const StudyTable& t) -> const auto& { return t.success_comparisons; }, experiment_success);
}

std::string success_csv(const std::vector<SuccessRow>& rows) {
  return pair_table_csv(rows, kSuccessColumns, [](const SuccessComparison& c) {
    return fmt::format("{},{},{},{},{},{},{},{},{},{},{}", c.successes_a, c.runs_a, c.successes_b, c.runs_b,
                       number_text(c.fisher.p_value), number_text(c.fisher_p_holm), number_text(c.fisher.odds_ratio),
                       number_text(c.censored.statistic), number_text(c.censored.p_value),
                       number_text(c.censored_p_holm), number_text(c.censored_at));
  });
}

nlohmann::ordered_json success_json(const std::vector<SuccessRow>& rows) {
  return pair_table_json(rows, [](const SuccessComparison& c) {
    return nlohmann::ordered_json{{"successes_a", c.successes_a},
                                  {"runs_a", c.runs_a},
                                  {"successes_b", c.successes_b},
                                  {"runs_b", c.runs_b},
                                  {"fisher_p", number_json(c.fisher.p_value)},
                                  {"fisher_p_holm", number_json(c.fisher_p_holm)},
                                  {"odds_ratio", number_json(c.fisher.odds_ratio)},
                                  {"censored_u", number_json(c.censored.statistic)},
                                  {"censored_p", number_json(c.censored.p_value)},
                                  {"censored_p_holm", number_json(c.censored_p_holm)},
                                  {"censored_at", number_json(c.censored_at)}};
  });
}

}  // namespace esc::report
