#include "cli/library_path.hpp"

#include <cstdlib>
#include <sstream>
#include <string>
#include <system_error>

namespace esc::cli {

std::filesystem::path standard_library_dir() {
  std::error_code ec;
  const std::filesystem::path binary = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  return (binary.parent_path() / ESC_STDLIB_FROM_BINARY).lexically_normal();
}

std::vector<std::filesystem::path> import_search_path() {
  std::vector<std::filesystem::path> dirs;
  if (const char* path = std::getenv("ESC_PATH")) {
    std::stringstream entries(path);
    for (std::string e; std::getline(entries, e, ':');)
      if (!e.empty()) dirs.emplace_back(e);
  }
  if (std::filesystem::path lib = standard_library_dir(); !lib.empty()) dirs.push_back(std::move(lib));
  return dirs;
}

}  // namespace esc::cli
