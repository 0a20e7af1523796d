#pragma once
// Checksums on the rows of the results database. A bit flipped in a stored gene, seed,
// statistic or population (a failing disk, a bad copy) leaves SQLite's own structure intact
// and would be read back as a valid, different value: a resumed run would finish with other
// results and exit 0. So every row of every table that esc reads carries, in its column
// `checksum`, a 64-bit FNV-1a hash of its other columns exactly as SQLite holds them (type
// and bytes), written in the transaction that writes the row and compared before anything
// stored is used (ResultsDb::load, which resume, dependency reuse, `start from`, report and
// export go through). FNV-1a changes its result for any change of one byte (each step is a
// bijection of the state), so a single flipped bit in a value or in its checksum is always
// found; docs/results-store.md lists what is covered.
#include <cstdint>
#include <filesystem>
#include <string_view>
#include <vector>

#include "runtime/store/sqlite.hpp"

namespace esc::store {

// Every table whose rows carry a checksum (all but `meta`, which nothing reads back).
[[nodiscard]] const std::vector<std::string_view>& sealed_tables();

// Writes the checksum of row `rowid` of `table`, inside the caller's transaction.
void seal_row(sql::Database& db, std::string_view table, std::int64_t rowid);
// Every row of `table` (a database upgraded to checksums: its rows are sealed as they are).
void seal_table(sql::Database& db, std::string_view table);

// Compares every row's checksum of every sealed table; throws StoreError naming `file`, the
// row (run, controller, generation where it has them) and what it holds, at the first
// mismatch.
void verify_rows(sql::Database& db, const std::filesystem::path& file);

}  // namespace esc::store
