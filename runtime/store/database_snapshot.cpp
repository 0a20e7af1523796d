#include "runtime/store/database_snapshot.hpp"

#include <stdlib.h>

#include <array>
#include <chrono>
#include <string>
#include <system_error>
#include <thread>

#include <fmt/format.h>

#include "runtime/store/results_db.hpp"
#include "runtime/store/write_ahead_log.hpp"

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
  const auto copy_of_one_moment = [&] {
    for (int attempt = 0; attempt < kTries; ++attempt) {
      const Stamp before = stamp(dir);
      for (const char* suffix : kFiles) {
        const fs::path file = dir / (std::string(kDatabaseFile) + suffix);
        const fs::path copy = dir_ / file.filename();
        fs::remove(copy);
        std::error_code ec;
        if (fs::exists(file, ec)) fs::copy_file(file, copy);
      }
      if (stamp(dir) == before) return;
    }
  };
  // A log being written can be copied between a frame's header and its page, over an older
  // frame: that reads as damage (write_ahead_log.hpp) until the page lands. A damaged log
  // is damaged in every copy; a write in progress ends within milliseconds.
  constexpr int kDamagedCopies = 4;
  constexpr auto kBetweenCopies = std::chrono::milliseconds(50);
  try {
    copy_of_one_moment();
    for (int copies = 1; copies < kDamagedCopies && log_damage(dir_ / kDatabaseFile); ++copies) {
      std::this_thread::sleep_for(kBetweenCopies);
      copy_of_one_moment();
    }
  } catch (const fs::filesystem_error& e) {
    std::error_code ec;
    fs::remove_all(dir_, ec);
    throw StoreError(fmt::format("cannot read {}: {}", dir.string(), e.code().message()));
  } catch (const StoreError&) {   // the copied log unreadable
    std::error_code ec;
    fs::remove_all(dir_, ec);
    throw;
  }
}

DatabaseSnapshot::~DatabaseSnapshot() {
  std::error_code ec;
  fs::remove_all(dir_, ec);
}

}  // namespace esc::store
