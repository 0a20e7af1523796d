#pragma once
// Compiling a script the way every command does: imports searched beside the file, then
// in $ESC_PATH, then in esc's standard library (cli/library_path.hpp); diagnostics
// rendered to stderr.
#include <filesystem>
#include <optional>
#include <utility>

#include <fmt/format.h>

#include "compiler/compiler.hpp"
#include "compiler/text.hpp"

namespace esc::cli {

[[nodiscard]] compiler::CompileOptions default_compile_options();

// True on the ranks of an MPI job other than rank 0: they compile and compute like rank 0
// but print nothing, so a job's output reads like one process's.
[[nodiscard]] bool follower_rank();

// fmt::print to stdout (say) or stderr (complain), on rank 0 or a lone process only.
template <typename... Args>
void say(fmt::format_string<Args...> format, Args&&... args) {
  if (!follower_rank()) fmt::print(format, std::forward<Args>(args)...);
}

template <typename... Args>
void complain(fmt::format_string<Args...> format, Args&&... args) {
  if (!follower_rank()) fmt::print(stderr, "{}", compiler::shorten_names(fmt::format(format, std::forward<Args>(args)...)));
}

// Compiles `file`, prints its diagnostics (colored on a terminal) to stderr (rank 0 only),
// returns the result whether or not it succeeded.
compiler::CompileResult load_script(const std::filesystem::path& file);
// The same with other import paths.
compiler::CompileResult load_script(const std::filesystem::path& file, const compiler::CompileOptions& options);

}  // namespace esc::cli
