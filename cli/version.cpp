#include "cli/version.hpp"

#include <cstdlib>

#include <fmt/format.h>

#include "app/version.hpp"
#include "cli/library_path.hpp"
#include "runtime/dist/mpi_session.hpp"

namespace esc::cli {

std::string version_text() {
  const char* esc_path = std::getenv("ESC_PATH");
  const std::filesystem::path library = standard_library_dir();
  const std::string commit = *kCommit != '\0' ? fmt::format(" (commit {})", kCommit) : std::string();
  return fmt::format("esc {}{}\n"
                     "optional parts: MPI {}, Google Benchmark (esc bench) {}, Python module (import esc) {}\n"
                     "standard library: {}\n"
                     "ESC_PATH: {}",
                     app::version(), commit, dist::built_with_mpi() ? "yes" : "no",
                     ESC_WITH_BENCHMARK ? "yes" : "no", ESC_WITH_PYTHON ? "yes" : "no", library.empty() ? "not found" : library.string(),
                     esc_path != nullptr ? esc_path : "(not set)");
}

}  // namespace esc::cli
