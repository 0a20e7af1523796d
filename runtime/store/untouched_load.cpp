#include "runtime/store/untouched_load.hpp"

#include <stdlib.h>

#include <algorithm>
#include <string>
#include <system_error>

#include <fmt/format.h>

namespace esc::store {

namespace fs = std::filesystem;

namespace {

// A temporary directory, removed with its contents.
class TemporaryCopy {
 public:
  TemporaryCopy() {
    std::string pattern = (fs::temp_directory_path() / "esc-check-XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr) throw StoreError("cannot create a temporary directory to check the run in");
    dir_ = pattern;
  }
  ~TemporaryCopy() {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  TemporaryCopy(const TemporaryCopy&) = delete;
  TemporaryCopy& operator=(const TemporaryCopy&) = delete;
  [[nodiscard]] const fs::path& dir() const noexcept { return dir_; }

 private:
  fs::path dir_;
};

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

bool no_generation(const std::vector<StoredExperiment>& all) {
  return std::all_of(all.begin(), all.end(), [](const StoredExperiment& e) {
    return std::all_of(e.controllers.begin(), e.controllers.end(), [](const StoredController& c) {
      return c.finished.empty() &&
             std::all_of(c.in_progress.begin(), c.in_progress.end(), [](const auto& s) { return s.generations.empty(); });
    });
  });
}

// Runs `read` on the database of `dir` opened from a copy in a temporary directory (its
// errors naming `dir`, never the copy).
template <class Read>
auto on_copy(const fs::path& dir, Read&& read) {
  const TemporaryCopy copy;
  try {
    std::error_code ec;
    for (const char* suffix : {"", "-wal"}) {
      const fs::path file = dir / (std::string(kDatabaseFile) + suffix);
      if (fs::exists(file, ec)) fs::copy_file(file, copy.dir() / file.filename());
    }
    ResultsDb db = ResultsDb::open(copy.dir());
    return read(db);
  } catch (const NothingStored& e) {
    throw NothingStored(replaced(e.what(), copy.dir().string(), dir.string()));
  } catch (const StoreError& e) {
    throw StoreError(replaced(e.what(), copy.dir().string(), dir.string()));
  } catch (const fs::filesystem_error& e) {
    throw StoreError(fmt::format("cannot read {}: {}", dir.string(), e.code().message()));
  }
}

}  // namespace

std::vector<StoredExperiment> load_untouched(const fs::path& dir) {
  std::error_code ec;
  // Not a directory, or no database: `open` says so before it opens anything.
  if (!fs::is_regular_file(dir / kDatabaseFile, ec)) return ResultsDb::open(dir, true).load();
  return on_copy(dir, [&](ResultsDb& db) {
    std::vector<StoredExperiment> all = db.load();
    if (no_generation(all))
      throw NothingStored(fmt::format("{} holds no committed generation: the run was stopped before its first",
                                      (dir / kDatabaseFile).string()));
    return all;
  });
}

std::vector<eval::ResumePoint> resume_points_untouched(const fs::path& dir,
                                                       const std::vector<const StoredExperiment*>& stored,
                                                       const std::vector<const eval::ExperimentSpec*>& specs) {
  return on_copy(dir, [&](ResultsDb& db) {
    std::vector<eval::ResumePoint> points;
    for (std::size_t i = 0; i < stored.size(); ++i)
      points.push_back(stored[i] != nullptr ? db.resume_point(*stored[i], *specs[i]) : eval::ResumePoint{});
    return points;
  });
}

bool holds_nothing_stored(const fs::path& dir) {
  std::error_code ec;
  if (!fs::is_regular_file(dir / kDatabaseFile, ec)) return false;
  try {
    (void)load_untouched(dir);
    return false;
  } catch (const NothingStored&) {
    return true;
  } catch (const StoreError&) {
    return false;
  }
}

}  // namespace esc::store
