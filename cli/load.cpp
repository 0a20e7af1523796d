#include "cli/load.hpp"

#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>

#include <unistd.h>

#include "runtime/dist/mpi_session.hpp"

namespace esc::cli {

compiler::CompileOptions default_compile_options() {
  compiler::CompileOptions o;
  if (const char* path = std::getenv("ESC_PATH")) {
    std::stringstream entries(path);
    for (std::string e; std::getline(entries, e, ':');)
      if (!e.empty()) o.import_paths.emplace_back(e);
  }
  o.import_paths.emplace_back(ESC_STDLIB_DIR);
  return o;
}

bool follower_rank() {
  const dist::MpiSession* mpi = dist::MpiSession::current();
  return mpi != nullptr && mpi->active() && !mpi->is_root();
}

compiler::CompileResult load_script(const std::filesystem::path& file) {
  compiler::CompileResult r = compiler::compile_file(file, default_compile_options());
  if (!r.diagnostics.empty() && !follower_rank())
    std::cerr << compiler::render_all(r.diagnostics, r.sources, isatty(STDERR_FILENO) != 0);
  return r;
}

}  // namespace esc::cli
