#pragma once
#include <filesystem>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "app/error.hpp"
#include "app/ranks.hpp"
#include "runtime/dist/mpi_session.hpp"
#include "runtime/store/results_db.hpp"

namespace esc::app {

// A problem with a stored directory (missing, foreign, damaged, mismatched), as the store
// reports it to whatever reads through this layer: what store_errors_typed turns into an
// Error, and what the readers of app/results.hpp throw.
using StoreError = store::StoreError;

// What `act` returns; a store::StoreError it throws (a directory missing, damaged or
// locked) becomes an Error of kind Results. In a job of several ranks it goes on as it is:
// it may have reached rank 0 alone, and the program must end the whole job.
template <typename F>
auto store_errors_typed(F&& act) -> decltype(act()) {
  try {
    return std::forward<F>(act)();
  } catch (const store::StoreError& e) {
    if (job() != nullptr && job()->size() > 1) throw;
    throw Error(ErrorKind::Results, e.what());
  }
}

// Throws an Error (ErrorKind::Results) saying that `dir` (or, where it does not exist yet,
// its nearest existing parent) is read-only for this process (a read-only mount, an archive,
// a colleague's results), with `help`: said before anything is written, instead of what the
// first write would say ("attempt to write a readonly database", "Permission denied").
void require_writable(const std::filesystem::path& dir, const std::string& what, const std::string& help);

// Whether the file system holding `dir` (or its nearest existing parent) has no room left
// for another generation: less than 1 MiB available.
[[nodiscard]] bool no_room_left(const std::filesystem::path& dir) noexcept;

// What `act` returns; an exception it throws while the disk holding `dir` is full (SQLite
// says only "database or disk is full", a stream only that it cannot write) becomes an
// Error of kind Results that names the directory and how to continue: every generation
// stored before is kept, as after a kill.
template <typename F>
auto disk_full_typed(const std::filesystem::path& dir, F&& act) -> decltype(act()) {
  try {
    return std::forward<F>(act)();
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    if (!no_room_left(dir)) throw;
    throw Error(ErrorKind::Results, fmt::format("the disk holding {} is full ({})", dir.string(), e.what()),
                fmt::format("free some space: `esc run --resume {}` continues from the last generation stored",
                            dir.string()));
  }
}

}  // namespace esc::app
