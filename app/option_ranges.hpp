#pragma once
// The ranges of the esc program's whole-number options, in one place: the command line
// checks its options against them (cli/command_line.cpp) and the Python module checks the
// same arguments against the same numbers (python/src/limits.cpp), so that `esc run
// --threads 5000` and `esc.run(threads=5000)` are refused alike. Seeds are any 64-bit
// unsigned integer (runtime/core/seed_text.hpp).
#include <string_view>

namespace esc::app {

struct OptionRange {
  long long lowest;
  long long highest;
  std::string_view text;   // the range as an error message says it
};

// Worker threads; 0 means all cores.
inline constexpr OptionRange kThreadsRange{0, 4096, "0 (all cores) to 4096"};
// Counts: runs, generations, runs at once, a run's number.
inline constexpr OptionRange kCountRange{1, 1'000'000'000, "at least 1"};

}  // namespace esc::app
