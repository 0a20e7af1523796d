#pragma once
// Where a script's imports are searched beyond its own directory: the directories of
// $ESC_PATH (colon-separated, searched first), then esc's standard library and shipped
// scripts. Where that library lies is the caller's to say: the esc program finds it relative
// to its own binary, the Python module relative to its package, an embedding program where
// it installed esc (find_package(esc) gives esc_STDLIB_DIR).
#include <filesystem>
#include <vector>

#include "compiler/compiler.hpp"

namespace esc::app {

// $ESC_PATH's directories, then `standard_library` (left out when empty).
[[nodiscard]] std::vector<std::filesystem::path> import_search_path(const std::filesystem::path& standard_library);

// A main script as a command is given it (`esc run FILE`, `esc check FILE`, esc.compile):
// `file` itself when it exists, is absolute or is empty; else the first directory of the
// search path above that holds it, as `import "FILE"` would find it (so `esc run
// paper/obstacle_avoidance.esc` runs the shipped script from any directory, installed
// too); else `file` as given, for the compiler to report missing.
[[nodiscard]] std::filesystem::path find_main_script(const std::filesystem::path& file,
                                                     const std::filesystem::path& standard_library);

// How every command compiles a script: imports searched as above.
[[nodiscard]] compiler::CompileOptions compile_options(const std::filesystem::path& standard_library);

}  // namespace esc::app
