#include "runtime/report/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

namespace esc::report {

Summary summarise(std::span<const double> sample) {
  Summary s;
  s.n = sample.size();
  if (s.n == 0) return s;
  std::vector<double> v(sample.begin(), sample.end());
  std::sort(v.begin(), v.end());
  const auto n = static_cast<double>(s.n);
  s.mean = std::accumulate(v.begin(), v.end(), 0.0) / n;
  double sq = 0.0;
  for (double x : v) sq += (x - s.mean) * (x - s.mean);
  s.sd = s.n > 1 ? std::sqrt(sq / (n - 1.0)) : 0.0;
  s.median = s.n % 2 == 1 ? v[s.n / 2] : 0.5 * (v[s.n / 2 - 1] + v[s.n / 2]);
  s.min = v.front();
  s.max = v.back();
  return s;
}

}  // namespace esc::report
