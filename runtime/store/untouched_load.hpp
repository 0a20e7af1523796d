#pragma once
// Reading a run directory without changing a byte of it. Opening esc.db with SQLite, even
// only to read, can write: the log of a killed run is folded into the database when the last
// connection closes, shared-memory and log files appear, an older schema is upgraded. A
// resume that is then refused (a damaged database, a changed script, nothing stored) must
// leave the directory exactly as it found it, so its checks read a copy of the database.
#include <filesystem>
#include <optional>
#include <vector>

#include "runtime/store/results_db.hpp"

namespace esc::store {

// Everything stored in `dir`, read from a copy of its database (and log) in a temporary
// directory, which is removed. Throws StoreError, its message naming `dir` and never the
// copy; NothingStored when no generation was committed.
[[nodiscard]] std::vector<StoredExperiment> load_untouched(const std::filesystem::path& dir);

// What load_untouched reads, and where the database's log was damaged, what SQLite dropped
// from it (write_ahead_log.hpp): the generations it held are not among `experiments`.
struct UntouchedRead {
  std::vector<StoredExperiment> experiments;
  std::optional<LogScan> log_damage;
};
[[nodiscard]] UntouchedRead read_untouched(const std::filesystem::path& dir);

// Whether `dir` holds an esc.db with no committed generation (an empty file, or a run
// stopped before its first generation), read without changing it.
[[nodiscard]] bool holds_nothing_stored(const std::filesystem::path& dir);

// The resume points of the experiments `stored[i]` (ResultsDb::resume_point with `specs[i]`;
// an empty point where stored[i] is null), read from a copy of `dir`'s database as
// load_untouched reads it: a carry-on refused here (a finished run without its state) leaves
// the directory as it was. Throws StoreError naming `dir`.
[[nodiscard]] std::vector<eval::ResumePoint> resume_points_untouched(
    const std::filesystem::path& dir, const std::vector<const StoredExperiment*>& stored,
    const std::vector<const eval::ExperimentSpec*>& specs);

}  // namespace esc::store
