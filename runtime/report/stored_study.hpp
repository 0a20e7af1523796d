#pragma once
// A study as its directory stores it, read the way the report and `esc export --table
// success|comparisons` compare it: its conditions in the study's order, each as the samples
// study_table() takes; and a plain experiment's comparisons of its controllers.
#include <vector>

#include "runtime/report/study_table.hpp"
#include "runtime/store/results_db.hpp"

namespace esc::report {

// The directory's conditions in the study's order; empty when it holds a plain experiment.
[[nodiscard]] std::vector<const store::StoredExperiment*> conditions_in_order(const store::StoredDirectory& d);

// Each controller's finished runs' best fitness and, where the condition declares a success
// test, their success sample.
[[nodiscard]] ConditionSamples condition_samples(const store::StoredExperiment& condition);

// A plain experiment's comparisons of its runs' best fitness: every pair of its controllers,
// one family (the end table's and the report's).
[[nodiscard]] std::vector<Comparison> experiment_comparisons(const store::StoredExperiment& e);

}  // namespace esc::report
