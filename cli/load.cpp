#include "cli/load.hpp"

#include <iostream>

#include <unistd.h>

#include "app/import_path.hpp"
#include "app/ranks.hpp"
#include "cli/library_path.hpp"

namespace esc::cli {

compiler::CompileOptions default_compile_options() { return app::compile_options(standard_library_dir()); }

bool follower_rank() { return app::follower_rank(); }

compiler::CompileResult load_script(const std::filesystem::path& file) {
  return load_script(file, default_compile_options());
}

compiler::CompileResult load_script(const std::filesystem::path& file, const compiler::CompileOptions& options) {
  compiler::CompileResult r = compiler::compile_file(file, options);
  if (!r.diagnostics.empty() && !follower_rank())
    std::cerr << compiler::render_all(r.diagnostics, r.sources, isatty(STDERR_FILENO) != 0);
  return r;
}

}  // namespace esc::cli
