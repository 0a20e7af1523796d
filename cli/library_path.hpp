#pragma once
// Where esc looks for what a script imports beyond its own directory: the directories of
// $ESC_PATH (colon-separated, searched first), then its standard library and shipped
// scripts, found relative to the esc binary itself (ESC_STDLIB_FROM_BINARY, normally
// ../share/esc/experiments). So an installed, packaged or moved esc reads its own library and
// never a path of the machine that built it; the build tree stages experiments/ at the same
// place beside build/cli/esc.
#include <filesystem>
#include <vector>

namespace esc::cli {

// The standard library of this esc binary; empty when the binary's own path cannot be read.
[[nodiscard]] std::filesystem::path standard_library_dir();

// $ESC_PATH's directories, then standard_library_dir().
[[nodiscard]] std::vector<std::filesystem::path> import_search_path();

// The script a command was given as FILE: app::find_main_script with this binary's library.
[[nodiscard]] std::filesystem::path find_main_script(const std::filesystem::path& file);

}  // namespace esc::cli
