#include "runtime/store/page_check.hpp"

#include <stdlib.h>
#include <unistd.h>

#include <filesystem>
#include <sstream>
#include <vector>

#include <fmt/format.h>

namespace esc::store {

namespace {

// `text` in a new file of the temporary directory; its path, or nothing where none can be
// written (the first problem is then all that is said).
std::optional<std::string> write_listing(const std::string& text) {
  std::error_code ec;
  std::string path = (std::filesystem::temp_directory_path(ec) / "esc-damage-XXXXXX.txt").string();
  if (ec) return std::nullopt;
  const int fd = mkstemps(path.data(), 4);
  if (fd < 0) return std::nullopt;
  const bool written = ::write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size());
  ::close(fd);
  if (written) return path;
  std::filesystem::remove(path, ec);
  return std::nullopt;
}

}  // namespace

std::optional<std::string> page_check_problem(sql::Database& db) {
  auto check = db.prepare("PRAGMA quick_check");
  std::vector<std::string> problems;
  std::string listing;
  while (check.step()) {
    // One row a problem, or one row of several lines ("*** in database main ***" heading
    // the b-tree's problems).
    std::istringstream lines(check.text(0));
    for (std::string line; std::getline(lines, line);) {
      listing += line + "\n";
      if (line != "ok" && !line.empty() && !line.starts_with("*** ")) problems.push_back(line);
    }
  }
  if (problems.empty() && !listing.empty()) return std::nullopt;
  if (problems.empty()) return "SQLite's check gave no answer";
  if (problems.size() == 1) return problems.front();
  const std::optional<std::string> file = write_listing(listing);
  if (!file) return fmt::format("{} ({} problems in all)", problems.front(), problems.size());
  return fmt::format("{} ({} problems in all, listed in {})", problems.front(), problems.size(), *file);
}

}  // namespace esc::store
