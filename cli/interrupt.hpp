#pragma once
// Ctrl-C (SIGINT) or SIGTERM during `esc run`: one line on stderr saying that the run in
// DIR stopped at its last stored generation and how to continue it, then the process ends
// as the signal ends it (status 128 + signal). The directory is as a kill leaves it: every
// generation it committed is kept, and `esc run --resume DIR` continues bit-identically.
#include <filesystem>

namespace esc::cli {

// From now on, a SIGINT or SIGTERM names `dir`. Called once the run's directory exists.
void on_interrupt_name(const std::filesystem::path& dir);

}  // namespace esc::cli
