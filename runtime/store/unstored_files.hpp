#pragma once
// What `esc run` writes into its directory before its first generation is committed, told
// apart from everything else. A run killed then has stored nothing, and `esc run --out`
// reuses its directory, deleting those files; any other file (a run's genome, a CSV of two
// generations, a summary holding a run, a report, a file of the user's) is kept, and so is
// the directory: a finished run whose esc.db was emptied is not a run that never started.
#include <filesystem>
#include <optional>
#include <string>

#include "runtime/store/results_db.hpp"

namespace esc::store {

// The first file or directory under `dir` that is not what a run writes before its first
// commit (deps/ aside, which is never deleted): none when the directory holds only these:
//   esc.db and its log files; sources/ and the files in it; settings.json; summary.json
//   holding no run; under any other directory (a controller's, a study condition's): its
//   settings.json and run-NN.csv files of at most one generation (the line appended
//   before generation 0 is committed); and a `.tmp` file each of these leaves when killed
//   while it is written.
[[nodiscard]] std::optional<std::filesystem::path> first_kept_file(const std::filesystem::path& dir);

// Throws NothingStored(`message`, `launch`) for `dir`, unless it holds a file a run writes
// only once it has stored something (first_kept_file): then StoreError saying that its
// database was emptied or replaced, and that nothing in it is reused or deleted.
[[noreturn]] void throw_nothing_stored(const std::filesystem::path& dir, const std::string& message,
                                       std::optional<NothingStored::Launch> launch = std::nullopt);

}  // namespace esc::store
