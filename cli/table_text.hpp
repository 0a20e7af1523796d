#pragma once
// How the end tables of `esc run` write numbers, p-values and the pairs they compare
// (end_table.cpp, success_table.cpp): one spelling for "undefined" and one precision per kind.
#include <cmath>
#include <cstddef>
#include <functional>
#include <string>

#include <fmt/format.h>

#include "runtime/report/fitness_decimals.hpp"

namespace esc::cli {

// "n/a" for an undefined value (NaN), else `decimals` decimals.
[[nodiscard]] inline std::string number_or_na(double x, int decimals) {
  return std::isnan(x) ? "n/a" : fmt::format("{:.{}f}", x, decimals);
}

using report::fitness_decimals;

// Four decimals, or two significant digits below 1e-4.
[[nodiscard]] inline std::string p_text(double p) {
  if (std::isnan(p)) return "n/a";
  return p < 1e-4 ? fmt::format("{:.1e}", p) : fmt::format("{:.4f}", p);
}

// "A vs B" for the samples a and b of a comparison.
using PairLabel = std::function<std::string(std::size_t, std::size_t)>;

}  // namespace esc::cli
