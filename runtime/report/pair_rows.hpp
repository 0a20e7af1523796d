#pragma once
// The rows of `esc export --table success` and `--table comparisons`: every pair the end table
// and the report compare (within an experiment every pair of its controllers, one family; in
// a study, study_table.hpp's pairs and family), one row each, with that table's test, so that
// a paper's table is made from the tests esc ran rather than copied from a page.
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "runtime/report/stored_study.hpp"
#include "runtime/report/study_table.hpp"
#include "runtime/store/results_db.hpp"

namespace esc::report {

// What a row compares.
struct PairNames {
  std::string study;        // empty for a plain experiment
  std::string experiment;   // the plain experiment; empty in a study (its conditions may differ)
  std::string condition_a, controller_a, condition_b, controller_b;   // conditions empty outside a study
};

template <class Test>
struct PairRow : PairNames {
  Test test;
};

// The names' six CSV fields, each followed by a comma; and the same as the first keys of a
// row's JSON object.
[[nodiscard]] std::string pair_names_csv(const PairNames& n);
[[nodiscard]] nlohmann::ordered_json pair_names_json(const PairNames& n);

// Every directory's rows: `of_study(table)` gives a study's tests (their a and b index its
// cells), `of_experiment(e)` a plain experiment's (a and b index its controllers).
template <class Test, class OfStudy, class OfExperiment>
[[nodiscard]] std::vector<PairRow<Test>> pair_rows(const std::vector<store::StoredDirectory>& directories,
                                                   OfStudy of_study, OfExperiment of_experiment) {
  std::vector<PairRow<Test>> rows;
  for (const store::StoredDirectory& d : directories) {
    const std::vector<const store::StoredExperiment*> conditions = conditions_in_order(d);
    if (!conditions.empty()) {
      std::vector<ConditionSamples> samples;
      for (const store::StoredExperiment* e : conditions) samples.push_back(condition_samples(*e));
      const StudyTable t = study_table(samples);
      for (const Test& c : of_study(t)) {
        const StudyCell& a = t.cells[c.a];
        const StudyCell& b = t.cells[c.b];
        rows.push_back({{conditions.front()->condition->study, {}, t.conditions[a.condition],
                         t.controllers[a.controller], t.conditions[b.condition], t.controllers[b.controller]},
                        c});
      }
      continue;
    }
    for (const store::StoredExperiment& e : d.experiments)
      for (const Test& c : of_experiment(e))
        rows.push_back({{{}, e.name, {}, e.controllers[c.a].name, {}, e.controllers[c.b].name}, c});
  }
  return rows;
}

// A pair table as CSV: `columns` (the names' six, then the test's), then a line per row, the
// test's fields written by `fields(test)`.
template <class Test, class Fields>
[[nodiscard]] std::string pair_table_csv(const std::vector<PairRow<Test>>& rows, const char* columns, Fields fields) {
  std::string out = std::string(columns) + "\n";
  for (const PairRow<Test>& r : rows) out += pair_names_csv(r) + fields(r.test) + "\n";
  return out;
}

// The same rows as JSON objects: the names' keys, then those of `fields(test)` in its order.
template <class Test, class Fields>
[[nodiscard]] nlohmann::ordered_json pair_table_json(const std::vector<PairRow<Test>>& rows, Fields fields) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const PairRow<Test>& r : rows) {
    nlohmann::ordered_json row = pair_names_json(r);
    row.update(fields(r.test));
    out.push_back(std::move(row));
  }
  return out;
}

// A number as these tables write it: 17 significant digits, `nan`, `inf`, `-inf`.
[[nodiscard]] std::string number_text(double x);
// In JSON: NaN as null, the infinities as "inf" and "-inf".
[[nodiscard]] nlohmann::ordered_json number_json(double x);

}  // namespace esc::report
