#pragma once
// Reading run directories, never changing them: their results as one table (`esc export`),
// or as one HTML report with its figures (`esc report`).
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "app/events.hpp"
#include "compiler/compiler.hpp"
#include "runtime/store/results_db.hpp"

namespace esc::app {

// The tables a directory exports: "generations" (per-generation statistics; the default),
// "usage" (steps each behavior acted), "metrics" (what each run's optimizer reported),
// "front" and "archive" (what NSGA-II, MAP-Elites and novelty search kept, per generation),
// "success" and "comparisons" (the end table's tests, a row per pair), "topology" (NEAT's
// networks).
inline constexpr std::string_view kTables[] = {"generations", "usage",   "metrics",    "front",
                                                "archive",     "success", "comparisons", "topology"};

// Where a directory's stored run is: the directory itself when it holds esc.db, else its
// parent when that does (a study's STUDY/CONDITION, or a controller's files), `condition`
// naming the directory under it; `found` is false when neither does. "DIR/" reads as DIR,
// and paths keep the spelling they were given.
struct RunLocation {
  std::filesystem::path root;
  std::string condition;
  bool found = false;
};
[[nodiscard]] RunLocation locate_run(std::filesystem::path dir);

// Everything stored where `at` locates `named` (a run's directory; for a study's condition,
// the whole study's), read from a snapshot of its database as `esc export` reads it, a
// damaged log told to `events` as a Warning note (log_damage_warning). Throws
// store::StoreError for a directory that is not a run's, or is damaged.
[[nodiscard]] std::vector<store::StoredExperiment> read_stored(const RunLocation& at, const std::filesystem::path& named,
                                                               Events& events);
// The one experiment run directory `dir` holds. Throws store::StoreError saying what it
// holds instead (a study, nothing) or what is wrong with it.
[[nodiscard]] store::StoredExperiment read_single(const std::filesystem::path& dir);
// Everything stored in `dir`, read from a copy of its database (store::read_untouched): not a
// byte of the directory changes, a killed run's log included, and a read-only directory
// reads. A damaged log is told to `events` as a Warning note (log_damage_warning).
[[nodiscard]] store::StoredDirectory read_untouched(const std::filesystem::path& dir, Events& events);

// What a reader of `root` says of its damaged write-ahead log (store::log_damage): the
// frames SQLite dropped, that what it holds is shown without them, and how to run them again.
[[nodiscard]] std::string log_damage_warning(const std::filesystem::path& root, const store::LogScan& scan);

// Table `table` of every directory in `dirs`, as CSV or (csv false) JSON; JSON without a
// table named is everything stored. A study's condition directory (STUDY/CONDITION) stands
// for that condition alone, here and in write_report. Throws store::StoreError for a
// directory that is not a run's, std::invalid_argument for an unknown table (naming the
// tables, and the nearest). A directory whose log is damaged is read as SQLite reads it,
// after a Warning note (log_damage_warning) to `events`.
// With `options` (how to compile a run's stored sources), the topology table also holds the
// final front's or archive's networks of each finished run of a NEAT network evolved by
// NSGA-II, novelty search or MAP-Elites (final_members); without, each run's best only.
[[nodiscard]] std::string export_text(const std::vector<std::filesystem::path>& dirs, std::string_view table, bool csv,
                                      Events& events, const compiler::CompileOptions* options = nullptr);
// The same of directories already read.
[[nodiscard]] std::string table_text(const std::vector<store::StoredDirectory>& dirs, std::string_view table, bool csv,
                                     const compiler::CompileOptions* options = nullptr);

struct ReportFiles {
  std::filesystem::path html;
  std::filesystem::path figures;   // the directory beside it holding each figure as SVG
  std::size_t figure_count = 0;
};

// One report of `dirs` written to `out` (default, when empty: DIR/report.html of a single
// directory), telling `events` of damaged logs as export_text does.
[[nodiscard]] ReportFiles write_report(const std::vector<std::filesystem::path>& dirs, std::filesystem::path out,
                                       Events& events);

}  // namespace esc::app
