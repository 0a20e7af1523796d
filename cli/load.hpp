#pragma once
// Compiling a script the way every command does: imports searched beside the file, then
// in $ESC_PATH, then in the shipped experiments/ directory; diagnostics rendered to stderr.
#include <filesystem>
#include <optional>

#include "compiler/compiler.hpp"

namespace esc::cli {

[[nodiscard]] compiler::CompileOptions default_compile_options();

// Compiles `file`, prints its diagnostics (colored on a terminal) to stderr, returns the
// result whether or not it succeeded.
compiler::CompileResult load_script(const std::filesystem::path& file);

}  // namespace esc::cli
