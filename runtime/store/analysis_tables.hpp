#pragma once
// The tables of the results database that section 4's analyses read (schema 4), apart from
// the rest of the store: behavior usage per generation (the paper's Figure 2), what each
// controller's choices are (their library, whether it is marked useless: how the report
// groups them), and where a transferred controller comes from (`start from` / `evaluate
// from`: its fitness in the origin experiment and here). Written in the same transactions as
// the rest of a generation, so resume keeps them exact.
#include <cstdint>
#include <optional>
#include <vector>

#include "runtime/control/controller_spec.hpp"
#include "runtime/eval/run_state.hpp"
#include "runtime/store/sqlite.hpp"

namespace esc::store {

// The schema version that added these tables: an older database has none of them.
inline constexpr int kAnalysisSchemaVersion = 4;

// The tables (CREATE TABLE statements), for a new database and for the upgrade to schema 4.
[[nodiscard]] const char* analysis_schema();

// A controller's choices, in ControllerSpec::choice_names() order.
void save_choices(sql::Database& db, std::int64_t controller_id, const std::vector<control::Choice>& choices);
[[nodiscard]] std::vector<control::Choice> load_choices(sql::Database& db, std::int64_t controller_id);

// The usage of a run's generation (nothing for a controller that has no choices).
void save_usage(sql::Database& db, std::int64_t controller_id, int run, const eval::GenerationStats& generation);
// Fills the usage of each of a run's `generations` that has some stored; `damaged` starts
// the StoreError thrown when rows do not match the generations they name.
void load_usage(sql::Database& db, std::int64_t controller_id, int run, std::vector<eval::GenerationStats>& generations,
                std::string_view damaged);

// Where a run's first genome came from.
void save_transfer(sql::Database& db, std::int64_t controller_id, int run, const eval::Transfer& transfer);
[[nodiscard]] std::optional<eval::Transfer> load_transfer(sql::Database& db, std::int64_t controller_id, int run);

}  // namespace esc::store
