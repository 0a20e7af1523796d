#pragma once
// A copy of a run directory's database (esc.db and its log) in a temporary directory, removed
// with it. Opening esc.db with SQLite, even to read, writes beside it (shared-memory and log
// files, the log of a killed run folded in when the last connection closes) and fails where
// nothing may be written (a read-only mount, a colleague's archive): reading a run reads a
// snapshot instead. A database being written while it is copied is copied again, so that
// the copy holds the database and its log as of one moment, and so is a log that reads as
// damaged (a frame copied half-written, write_ahead_log.hpp) until the damage persists.
#include <filesystem>

namespace esc::store {

class DatabaseSnapshot {
 public:
  // Throws StoreError (naming `dir`) when the temporary directory cannot be made or the
  // files cannot be read.
  explicit DatabaseSnapshot(const std::filesystem::path& dir);
  ~DatabaseSnapshot();
  DatabaseSnapshot(const DatabaseSnapshot&) = delete;
  DatabaseSnapshot& operator=(const DatabaseSnapshot&) = delete;

  // The temporary directory holding the copy (its esc.db, and esc.db-wal where there was one).
  [[nodiscard]] const std::filesystem::path& dir() const noexcept { return dir_; }

 private:
  std::filesystem::path dir_;
};

}  // namespace esc::store
