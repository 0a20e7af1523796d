#pragma once
// How the end tables of `esc run` write numbers and p-values (end_table.cpp,
// success_table.cpp): one spelling for "undefined" and one precision per kind.
#include <cmath>
#include <string>

#include <fmt/format.h>

namespace esc::cli {

// "n/a" for an undefined value (NaN), else `decimals` decimals.
[[nodiscard]] inline std::string number_or_na(double x, int decimals) {
  return std::isnan(x) ? "n/a" : fmt::format("{:.{}f}", x, decimals);
}

// Four decimals, or two significant digits below 1e-4.
[[nodiscard]] inline std::string p_text(double p) {
  if (std::isnan(p)) return "n/a";
  return p < 1e-4 ? fmt::format("{:.1e}", p) : fmt::format("{:.4f}", p);
}

}  // namespace esc::cli
