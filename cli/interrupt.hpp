#pragma once
// Ctrl-C (SIGINT) or SIGTERM during `esc run`: one line on stderr saying that the run in
// DIR stopped at its last stored generation (after how many of how many) and how to
// continue it, then the process ends as the signal ends it (status 128 + signal). The
// directory is as a kill leaves it: every generation it committed is kept, and
// `esc run --resume DIR` continues bit-identically.
#include <cstdint>
#include <filesystem>

namespace esc::cli {

// From now on, a SIGINT or SIGTERM names `dir`. Called once the run's directory exists.
void on_interrupt_name(const std::filesystem::path& dir);

// The generations of the campaign (all its runs) finished so far, of `generations`: the line
// says after how many it stopped. Called as they finish (an atomic store).
void on_interrupt_count(std::int64_t generations_done, std::int64_t generations);

}  // namespace esc::cli
