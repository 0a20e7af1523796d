#pragma once
// `esc export`: the results database as JSON (everything) or CSV (the per-generation
// statistics of every run, one row per generation, ready for R or pandas).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "runtime/store/results_db.hpp"

namespace esc::store {

[[nodiscard]] nlohmann::ordered_json export_json(const std::vector<StoredExperiment>& experiments);

// Columns: experiment,controller,run,run_seed,status,generation,best,mean,sd,evaluations,steps,seconds
// (run counts from 1, generation from 0; numbers with 17 significant digits).
[[nodiscard]] std::string export_csv(const std::vector<StoredExperiment>& experiments);

}  // namespace esc::store
