#pragma once
// SQLite's own check of a database's pages (PRAGMA quick_check), said in one line. SQLite
// lists one problem a line, and a damaged database has many: a killed run's esc.db cut in
// half has a "Page N is never used" for every page past the cut, dozens of lines. The first
// problem says what is wrong; all of them go to a file in the temporary directory, named in
// the line (never beside the database: a refusal leaves a run directory as it found it).
#include <optional>
#include <string>

#include "runtime/store/sqlite.hpp"

namespace esc::store {

// Nothing when the check passes; else "FIRST PROBLEM" or, with more than one, "FIRST PROBLEM
// (N problems in all, listed in FILE)". Throws sql::SqliteError where SQLite cannot check.
[[nodiscard]] std::optional<std::string> page_check_problem(sql::Database& db);

}  // namespace esc::store
