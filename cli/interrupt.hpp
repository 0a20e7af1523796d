#pragma once
// Ctrl-C (SIGINT) or SIGTERM during `esc run`: one line on stderr saying that the run in
// DIR stopped at its last stored generation (after how many of how many, a study's every
// condition counted) and how to continue it, or, stopped before its first generation was
// stored, how to start it again (a resume would find nothing to continue); then the
// process ends as the signal ends it (status 128 + signal). The directory is as a kill
// leaves it: every generation it committed is kept, and `esc run --resume DIR` continues
// bit-identically.
#include <cstdint>
#include <filesystem>
#include <string>

namespace esc::cli {

// From now on, a SIGINT or SIGTERM names `dir`, whose runs (a study's: every condition's)
// make `generations`, `stored` of them stored already; `restart` is the command that starts
// it again (empty: a resumed run, which has stored some). Called once the directory exists.
void on_interrupt_name(const std::filesystem::path& dir, std::int64_t generations, std::int64_t stored,
                       const std::string& restart);

// Held while a generation is committed: a SIGINT or SIGTERM that comes meanwhile waits for
// the commit to end (milliseconds), so that the line counts the generation exactly when it
// was stored; a second signal stops at once.
class StoringGeneration {
 public:
  StoringGeneration();
  ~StoringGeneration();   // a signal that came meanwhile stops the process now
  StoringGeneration(const StoringGeneration&) = delete;
  StoringGeneration& operator=(const StoringGeneration&) = delete;
  void stored();          // committed: one more generation counted
};

}  // namespace esc::cli
