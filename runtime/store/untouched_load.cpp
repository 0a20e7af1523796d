#include "runtime/store/untouched_load.hpp"

#include <algorithm>
#include <string>
#include <system_error>

#include <fmt/format.h>

#include "runtime/store/database_snapshot.hpp"
#include "runtime/store/unstored_files.hpp"

namespace esc::store {

namespace fs = std::filesystem;

namespace {

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
// errors naming `dir`, never the copy; nothing stored only where `dir` holds nothing else
// a run stores).
template <class Read>
auto on_copy(const fs::path& dir, Read&& read) {
  const DatabaseSnapshot copy(dir);
  try {
    ResultsDb db = ResultsDb::open(copy.dir());
    return read(db);
  } catch (const NothingStored& e) {
    throw_nothing_stored(dir, replaced(e.what(), copy.dir().string(), dir.string()), e.launch());
  } catch (const StoreError& e) {
    throw StoreError(replaced(e.what(), copy.dir().string(), dir.string()));
  }
}

}  // namespace

std::vector<StoredExperiment> load_untouched(const fs::path& dir) { return read_untouched(dir).experiments; }

UntouchedRead read_untouched(const fs::path& dir) {
  std::error_code ec;
  // Not a directory, or no database: `open` says so before it opens anything.
  if (!fs::is_regular_file(dir / kDatabaseFile, ec)) return {ResultsDb::open(dir, true).load(), std::nullopt};
  return on_copy(dir, [&](ResultsDb& db) {
    std::vector<StoredExperiment> all = db.load();
    if (no_generation(all)) {
      const StoredExperiment& e = all.front();
      const fs::path file = dir / kDatabaseFile;
      throw NothingStored(
          db.log_damage() ? fmt::format("{}; its valid part holds no committed generation",
                                        log_damage_text(file, *db.log_damage()))
                          : fmt::format("{} holds no committed generation: the run was stopped before its first",
                                        file.string()),
          NothingStored::Launch{e.script, e.condition ? e.condition->study : e.name, e.overrides});
    }
    return UntouchedRead{std::move(all), db.log_damage()};
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
