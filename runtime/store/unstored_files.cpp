#include "runtime/store/unstored_files.hpp"

#include <fstream>
#include <string_view>
#include <system_error>

#include <fmt/format.h>

namespace esc::store {

namespace fs = std::filesystem;

namespace {

// The file a `.tmp` is written for (write_atomically): what it is cut short of.
std::string written_name(const fs::path& p) {
  constexpr std::string_view kTmp = ".tmp";
  std::string name = p.filename().string();
  if (name.size() > kTmp.size() && name.ends_with(kTmp)) name.resize(name.size() - kTmp.size());
  return name;
}

bool is_database_file(const std::string& name) {
  const std::string db = kDatabaseFile;
  return name == db || name == db + "-wal" || name == db + "-shm" || name == db + "-journal";
}

// Whether a run-NN.csv holds more than its header and one generation's line.
bool holds_two_generations(const fs::path& csv) {
  std::ifstream in(csv, std::ios::binary);
  int lines = 0;
  for (char ch = 0; lines < 3 && in.get(ch);) lines += ch == '\n' ? 1 : 0;
  return lines > 2;
}

// Every finished run's entry in summary.json holds its best fitness; the summary written
// before any run finished holds none (nor does a `.tmp` of it cut short before one).
bool holds_a_run(const fs::path& summary) {
  std::ifstream in(summary, std::ios::binary);
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  return text.find("\"best_fitness\"") != std::string::npos;
}

// Below the top: a controller's directory, or a study condition's (its settings.json and
// its controllers' directories).
std::optional<fs::path> first_kept_below(const fs::path& dir) {
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (e.is_directory(ec)) {
      if (auto kept = first_kept_below(e.path())) return kept;
      continue;
    }
    if (!e.is_regular_file(ec)) return e.path();
    if (written_name(e.path()) == "settings.json") continue;
    if (name.starts_with("run-") && name.ends_with(".csv") && !holds_two_generations(e.path())) continue;
    return e.path();
  }
  return std::nullopt;
}

}  // namespace

std::optional<fs::path> first_kept_file(const fs::path& dir) {
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (name == kDependencyCache) continue;
    if (e.is_directory(ec)) {
      if (name == "sources") {
        for (const fs::directory_entry& s : fs::directory_iterator(e.path(), ec))
          if (!s.is_regular_file(ec)) return s.path();
        continue;
      }
      if (auto kept = first_kept_below(e.path())) return kept;
      continue;
    }
    if (!e.is_regular_file(ec)) return e.path();
    const std::string written = written_name(e.path());
    if (is_database_file(name) || written == "settings.json") continue;
    if (written == "summary.json" && !holds_a_run(e.path())) continue;
    return e.path();
  }
  return std::nullopt;
}

void throw_nothing_stored(const fs::path& dir, const std::string& message, std::optional<NothingStored::Launch> launch) {
  if (const auto kept = first_kept_file(dir))
    throw StoreError(fmt::format("{} holds nothing, but `{}` holds a run's results ({}): its database was emptied or "
                                 "replaced after they were stored (the run did not stop before it started); nothing "
                                 "in it is reused or deleted",
                                 (dir / kDatabaseFile).string(), dir.string(),
                                 kept->lexically_relative(dir).generic_string()));
  throw NothingStored(message, std::move(launch));
}

}  // namespace esc::store
