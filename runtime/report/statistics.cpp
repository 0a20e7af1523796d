#include "runtime/report/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <limits>
#include <vector>

#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>

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

TestResult welch_t_test(std::span<const double> a, std::span<const double> b) {
  TestResult r;
  r.p_value = std::numeric_limits<double>::quiet_NaN();
  if (a.size() < 2 || b.size() < 2) return r;
  const Summary sa = summarise(a);
  const Summary sb = summarise(b);
  const double va = sa.sd * sa.sd / static_cast<double>(sa.n);
  const double vb = sb.sd * sb.sd / static_cast<double>(sb.n);
  const double se2 = va + vb;
  if (!(se2 > 0.0)) return r;
  r.statistic = (sa.mean - sb.mean) / std::sqrt(se2);
  r.df = se2 * se2 / (va * va / static_cast<double>(sa.n - 1) + vb * vb / static_cast<double>(sb.n - 1));
  const boost::math::students_t dist(r.df);
  r.p_value = std::min(1.0, 2.0 * boost::math::cdf(boost::math::complement(dist, std::fabs(r.statistic))));
  return r;
}

TestResult mann_whitney_u(std::span<const double> a, std::span<const double> b) {
  TestResult r;
  r.p_value = std::numeric_limits<double>::quiet_NaN();
  if (a.empty() || b.empty()) return r;
  struct Value {
    double x;
    bool first;
  };
  std::vector<Value> all;
  for (double x : a) all.push_back({x, true});
  for (double x : b) all.push_back({x, false});
  std::sort(all.begin(), all.end(), [](const Value& l, const Value& m) { return l.x < m.x; });
  const auto n = static_cast<double>(all.size());
  double rank_sum_a = 0.0;
  double ties = 0.0;   // sum of t^3 - t over groups of tied values
  for (std::size_t i = 0; i < all.size();) {
    std::size_t j = i;
    while (j < all.size() && all[j].x == all[i].x) ++j;
    const double average_rank = 0.5 * static_cast<double>(i + 1 + j);   // ranks i+1 .. j
    for (std::size_t k = i; k < j; ++k)
      if (all[k].first) rank_sum_a += average_rank;
    const auto t = static_cast<double>(j - i);
    ties += t * t * t - t;
    i = j;
  }
  const auto n1 = static_cast<double>(a.size());
  const auto n2 = static_cast<double>(b.size());
  r.statistic = rank_sum_a - n1 * (n1 + 1.0) / 2.0;
  const double mu = n1 * n2 / 2.0;
  const double var = n1 * n2 / 12.0 * ((n + 1.0) - ties / (n * (n - 1.0)));
  if (!(var > 0.0)) return r;
  const double u = std::max(r.statistic, n1 * n2 - r.statistic);   // the larger U
  const double z = (u - mu - 0.5) / std::sqrt(var);
  const boost::math::normal_distribution<double> normal;
  r.p_value = std::min(1.0, 2.0 * boost::math::cdf(boost::math::complement(normal, z)));
  return r;
}

}  // namespace esc::report
