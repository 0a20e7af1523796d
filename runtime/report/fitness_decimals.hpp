#pragma once
// How many decimals a fitness is shown with, shared by the end tables of `esc run` and the
// replay's picture and line (app/replay.hpp), so a value reads the same in both.
#include <algorithm>
#include <cmath>

namespace esc::report {

// Decimals for fitness values whose largest magnitude is `largest`: `least` (one in the end
// tables, as the paper prints) down to 1; below it three significant digits (a maze's
// -0.0123 m, not -0.0).
[[nodiscard]] inline int fitness_decimals(double largest, int least = 1) {
  largest = std::abs(largest);
  if (!(largest < 1.0) || largest == 0.0) return least;   // NaN and infinities too
  return std::clamp(2 - static_cast<int>(std::floor(std::log10(largest))), least, 10);
}

}  // namespace esc::report
