#pragma once
// Compiling a script the way every command does: imports searched beside the file, then
// in $ESC_PATH, then in the shipped experiments/ directory; diagnostics rendered to stderr.
#include <filesystem>
#include <optional>

#include "compiler/compiler.hpp"

namespace esc::cli {

[[nodiscard]] compiler::CompileOptions default_compile_options();

// True on the ranks of an MPI job other than rank 0: they compile and compute like rank 0
// but print nothing, so a job's output reads like one process's.
[[nodiscard]] bool follower_rank();

// Compiles `file`, prints its diagnostics (colored on a terminal) to stderr (rank 0 only),
// returns the result whether or not it succeeded.
compiler::CompileResult load_script(const std::filesystem::path& file);

}  // namespace esc::cli
