#include "runtime/report/success_table.hpp"

#include <cmath>

#include <fmt/format.h>

#include "runtime/report/comparisons.hpp"
#include "runtime/report/stored_study.hpp"
#include "runtime/store/export.hpp"

namespace esc::report {

namespace {

std::string number_text(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  return fmt::format("{:.17g}", x);
}

nlohmann::ordered_json number_json(double x) {
  if (std::isnan(x)) return nullptr;
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  return x;
}

}  // namespace

std::vector<SuccessComparison> experiment_success(const store::StoredExperiment& e) {
  if (e.settings.count("success") == 0) return {};
  std::vector<SuccessSample> samples;
  for (const store::StoredController& c : e.controllers) samples.push_back(success_sample(c.finished));
  return compare_success(samples, all_pairs(samples.size()));
}

std::vector<SuccessRow> success_rows(const std::vector<store::StoredDirectory>& directories) {
  std::vector<SuccessRow> rows;
  for (const store::StoredDirectory& d : directories) {
    const std::vector<const store::StoredExperiment*> conditions = conditions_in_order(d);
    if (!conditions.empty()) {
      std::vector<ConditionSamples> samples;
      for (const store::StoredExperiment* e : conditions) samples.push_back(condition_samples(*e));
      const StudyTable t = study_table(samples);
      for (const SuccessComparison& c : t.success_comparisons) {
        const StudyCell& a = t.cells[c.a];
        const StudyCell& b = t.cells[c.b];
        rows.push_back({conditions.front()->condition->study, {}, t.conditions[a.condition],
                        t.controllers[a.controller], t.conditions[b.condition], t.controllers[b.controller], c});
      }
      continue;
    }
    for (const store::StoredExperiment& e : d.experiments)
      for (const SuccessComparison& c : experiment_success(e))
        rows.push_back({{}, e.name, {}, e.controllers[c.a].name, {}, e.controllers[c.b].name, c});
  }
  return rows;
}

std::string success_csv(const std::vector<SuccessRow>& rows) {
  std::string out = std::string(kSuccessColumns) + "\n";
  for (const SuccessRow& r : rows) {
    const SuccessComparison& c = r.test;
    out += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", store::csv_field(r.study),
                       store::csv_field(r.experiment), store::csv_field(r.condition_a), store::csv_field(r.controller_a),
                       store::csv_field(r.condition_b), store::csv_field(r.controller_b), c.successes_a, c.runs_a,
                       c.successes_b, c.runs_b, number_text(c.fisher.p_value), number_text(c.fisher_p_holm),
                       number_text(c.fisher.odds_ratio), number_text(c.censored.statistic),
                       number_text(c.censored.p_value), number_text(c.censored_p_holm), number_text(c.censored_at));
  }
  return out;
}

nlohmann::ordered_json success_json(const std::vector<SuccessRow>& rows) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const SuccessRow& r : rows) {
    const SuccessComparison& c = r.test;
    out.push_back({{"study", r.study},
                   {"experiment", r.experiment},
                   {"condition_a", r.condition_a},
                   {"controller_a", r.controller_a},
                   {"condition_b", r.condition_b},
                   {"controller_b", r.controller_b},
                   {"successes_a", c.successes_a},
                   {"runs_a", c.runs_a},
                   {"successes_b", c.successes_b},
                   {"runs_b", c.runs_b},
                   {"fisher_p", number_json(c.fisher.p_value)},
                   {"fisher_p_holm", number_json(c.fisher_p_holm)},
                   {"odds_ratio", number_json(c.fisher.odds_ratio)},
                   {"censored_u", number_json(c.censored.statistic)},
                   {"censored_p", number_json(c.censored.p_value)},
                   {"censored_p_holm", number_json(c.censored_p_holm)},
                   {"censored_at", number_json(c.censored_at)}});
  }
  return out;
}

}  // namespace esc::report
