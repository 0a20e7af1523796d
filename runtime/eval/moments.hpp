#pragma once
// Mean and sample standard deviation that stay finite for every finite sample: a
// generation's fitness statistics and the report's summaries. Fitness saturates at
// +-1e300, where (x - mean)^2 and a sum over many evaluations overflow; there the sample
// is scaled by its largest magnitude first. Within the range where the plain two-pass
// formulas are finite they are used unchanged, so results computed before stay bit for bit.
#include <span>

namespace esc::eval {

struct Moments {
  double mean = 0.0;
  double sd = 0.0;   // n - 1 in the denominator; 0 for one value
};

// Of a non-empty sample; NaN for both when a value is not finite.
[[nodiscard]] Moments moments(std::span<const double> sample) noexcept;

}  // namespace esc::eval
