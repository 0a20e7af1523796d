#include "app/import_path.hpp"

#include <cstdlib>
#include <sstream>
#include <string>
#include <system_error>

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

std::filesystem::path find_main_script(const std::filesystem::path& file,
                                       const std::filesystem::path& standard_library) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (file.empty() || file.is_absolute() || fs::exists(file, ec)) return file;
  for (const fs::path& dir : import_search_path(standard_library))
    if (const fs::path found = (dir / file).lexically_normal(); fs::is_regular_file(found, ec)) return found;
  return file;
}

compiler::CompileOptions compile_options(const std::filesystem::path& standard_library) {
  compiler::CompileOptions o;
  o.import_paths = import_search_path(standard_library);
  return o;
}

}  // namespace esc::app
