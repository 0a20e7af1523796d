#pragma once
// What a run's optimizer keeps in the results database (schema 6): its whole state after the
// run's last finished generation (table optimizer_state: the algorithm, the layout of its
// bytes, the bytes, as eval::OptimizerState holds them), and its own numbers per generation
// (table metrics: CMA-ES's step size, ...). The bytes are stored as they are, so a resumed
// run is bit-identical to the run that was not interrupted.
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "runtime/eval/run_state.hpp"
#include "runtime/store/sqlite.hpp"

namespace esc::store {

// Writes (or replaces) the state of run `run` of the controller with id `controller_id`.
void save_state(sql::Database& db, std::int64_t controller_id, int run, const eval::OptimizerState& state);
// The state stored for that run by schema 6 or later; nullopt when there is none.
[[nodiscard]] std::optional<eval::OptimizerState> load_optimizer_state(sql::Database& db, std::int64_t controller_id,
                                                                       int run);

// Writes generation `g`'s metrics of that run.
void save_metrics(sql::Database& db, std::int64_t controller_id, int run, const eval::GenerationStats& g);
// Fills each generation's metrics of that run, in the order they were written. Throws
// StoreError, its message starting with `damaged`, for a generation beyond `gens`.
void load_metrics(sql::Database& db, std::int64_t controller_id, int run, std::vector<eval::GenerationStats>& gens,
                  std::string_view damaged);

}  // namespace esc::store
