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

// How every command compiles a script: imports searched as above.
[[nodiscard]] compiler::CompileOptions compile_options(const std::filesystem::path& standard_library);

}  // namespace esc::app
