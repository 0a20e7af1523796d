#include "app/import_path.hpp"

#include <cstdlib>
#include <sstream>
#include <string>

namespace esc::app {

std::vector<std::filesystem::path> import_search_path(const std::filesystem::path& standard_library) {
  std::vector<std::filesystem::path> dirs;
  if (const char* path = std::getenv("ESC_PATH")) {
    std::stringstream entries(path);
    for (std::string e; std::getline(entries, e, ':');)
      if (!e.empty()) dirs.emplace_back(e);
  }
  if (!standard_library.empty()) dirs.push_back(standard_library);
  return dirs;
}

compiler::CompileOptions compile_options(const std::filesystem::path& standard_library) {
  compiler::CompileOptions o;
  o.import_paths = import_search_path(standard_library);
  return o;
}

}  // namespace esc::app
