#pragma once
// Descriptive statistics of a sample (final best fitness over runs, ...).
#include <span>

namespace esc::report {

struct Summary {
  std::size_t n = 0;
  double mean = 0.0;
  double sd = 0.0;       // sample standard deviation (n - 1); 0 for n < 2
  double median = 0.0;
  double min = 0.0;
  double max = 0.0;
};

[[nodiscard]] Summary summarise(std::span<const double> sample);

}  // namespace esc::report
