#pragma once
// `esc export`: the results databases of one or more run directories (experiments or
// studies, made at different times) as JSON (everything) or CSV (the per-generation
// statistics of every run, one row per generation: one long table, ready for R or pandas).
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "runtime/store/results_db.hpp"

namespace esc::store {

// {"format", "schema_version", "experiments": [every experiment of every directory, with its
// "directory" and, for a study's condition, "study", "condition", "condition_settings"]}.
[[nodiscard]] nlohmann::ordered_json export_json(const std::vector<StoredDirectory>& directories);

// Columns: experiment,controller,run,run_seed,status,generation,best,mean,sd,evaluations,steps,
// seconds,condition,study,directory,algorithm (run counts from 1, generation from 0; numbers
// with 17 significant digits; a plain experiment's condition is its own name and its study
// empty; the algorithm that evolved the controller, `evaluate` for one only evaluated).
[[nodiscard]] std::string export_csv(const std::vector<StoredDirectory>& directories);

// Every run of every controller of every experiment of `directories`, in directory,
// experiment, controller and run order (finished runs first, as stored, then those in
// progress): f(experiment, its condition's name ("" for a plain experiment), controller,
// run from 0, its generations). The tidy tables (usage, metrics) are made of these.
void for_each_run(const std::vector<StoredDirectory>& directories,
                  const std::function<void(const StoredExperiment&, const std::string&, const StoredController&, int,
                                           const std::vector<eval::GenerationStats>&)>& f);

// A CSV field: quoted when it holds a comma, a quote or a line break (a directory's path, a
// sweep point's name, a behavior's arguments may).
[[nodiscard]] std::string csv_field(const std::string& text);

}  // namespace esc::store
