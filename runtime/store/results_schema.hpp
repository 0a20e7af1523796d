#pragma once
// The tables of a results database as this esc creates them (schema kSchemaVersion, in
// docs/results-store.md): created whole for a new database, and copied table by table from
// here when an older one is upgraded (results_migrations.cpp).

namespace esc::store {

// Every table but those of analysis_tables.hpp and member_tables.hpp.
[[nodiscard]] const char* results_schema();

}  // namespace esc::store
