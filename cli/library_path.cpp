#include "cli/library_path.hpp"

#include <system_error>

#include <sys/auxv.h>

#include "app/import_path.hpp"

namespace esc::cli {

namespace {

// This process's executable: /proc/self/exe, else (no /proc: a chroot, a container without
// it) the path it was started by, from the auxiliary vector, with its links resolved.
std::filesystem::path own_binary() {
  std::error_code ec;
  std::filesystem::path binary = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) return binary;
  const auto* started_as = reinterpret_cast<const char*>(getauxval(AT_EXECFN));
  if (started_as == nullptr) return {};
  binary = std::filesystem::weakly_canonical(std::filesystem::absolute(started_as, ec), ec);
  return ec ? std::filesystem::path() : binary;
}

}  // namespace

std::filesystem::path standard_library_dir() {
  const std::filesystem::path binary = own_binary();
  if (binary.empty()) return {};
  return (binary.parent_path() / ESC_STDLIB_FROM_BINARY).lexically_normal();
}

std::vector<std::filesystem::path> import_search_path() { return app::import_search_path(standard_library_dir()); }

std::filesystem::path find_main_script(const std::filesystem::path& file) {
  return app::find_main_script(file, standard_library_dir());
}

}  // namespace esc::cli
