#include "runtime/store/database_snapshot.hpp"

#include <stdlib.h>

#include <array>
#include <string>
#include <system_error>

#include <fmt/format.h>

#include "runtime/store/results_db.hpp"

namespace esc::store {

namespace fs = std::filesystem;

namespace {

constexpr std::array<const char*, 2> kFiles = {"", "-wal"};

// Size and modification time of the database and its log: equal before and after a copy,
// nothing was written while it was made.
struct Stamp {
  std::array<std::uintmax_t, kFiles.size()> sizes{};
  std::array<fs::file_time_type, kFiles.size()> times{};
  bool operator==(const Stamp&) const = default;
};

Stamp stamp(const fs::path& dir) {
  Stamp s;
  for (std::size_t i = 0; i < kFiles.size(); ++i) {
    const fs::path file = dir / (std::string(kDatabaseFile) + kFiles[i]);
    std::error_code ec;
    s.sizes[i] = fs::file_size(file, ec);
    if (ec) s.sizes[i] = static_cast<std::uintmax_t>(-1);
    s.times[i] = fs::last_write_time(file, ec);
  }
  return s;
}

}  // namespace

DatabaseSnapshot::DatabaseSnapshot(const fs::path& dir) {
  std::string pattern = (fs::temp_directory_path() / "esc-read-XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr)
    throw StoreError(fmt::format("cannot create a temporary directory to read {} in", dir.string()));
  dir_ = pattern;
  // A writer commits every generation: a few tries find a moment between two commits.
  constexpr int kTries = 5;
  try {
    for (int attempt = 0; attempt < kTries; ++attempt) {
      const Stamp before = stamp(dir);
      for (const char* suffix : kFiles) {
        const fs::path file = dir / (std::string(kDatabaseFile) + suffix);
        const fs::path copy = dir_ / file.filename();
        fs::remove(copy);
        std::error_code ec;
        if (fs::exists(file, ec)) fs::copy_file(file, copy);
      }
      if (stamp(dir) == before) break;
    }
  } catch (const fs::filesystem_error& e) {
    std::error_code ec;
    fs::remove_all(dir_, ec);
    throw StoreError(fmt::format("cannot read {}: {}", dir.string(), e.code().message()));
  }
}

DatabaseSnapshot::~DatabaseSnapshot() {
  std::error_code ec;
  fs::remove_all(dir_, ec);
}

}  // namespace esc::store
