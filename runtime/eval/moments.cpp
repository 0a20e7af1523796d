#include "runtime/eval/moments.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace esc::eval {

namespace {

// The two-pass formulas on x / scale, multiplied back.
Moments two_pass(std::span<const double> x, double scale) noexcept {
  const auto n = static_cast<double>(x.size());
  double sum = 0.0;
  for (const double v : x) sum += v / scale;
  const double mean = sum / n;
  double sq = 0.0;
  for (const double v : x) sq += (v / scale - mean) * (v / scale - mean);
  return {mean * scale, x.size() > 1 ? std::sqrt(sq / (n - 1.0)) * scale : 0.0};
}

}  // namespace

Moments moments(std::span<const double> sample) noexcept {
  const Moments plain = two_pass(sample, 1.0);
  if (std::isfinite(plain.mean) && std::isfinite(plain.sd)) return plain;
  double largest = 0.0;
  for (const double v : sample) {
    if (!std::isfinite(v)) return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
    largest = std::max(largest, std::abs(v));
  }
  return two_pass(sample, largest);
}

}  // namespace esc::eval
