#include "runtime/report/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

#include <boost/math/distributions/fisher_f.hpp>
#include <boost/math/distributions/hypergeometric.hpp>
#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>

#include "runtime/eval/moments.hpp"

namespace esc::report {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TestResult undefined() { return {kNaN, kNaN, kNaN, false}; }

double median_of_sorted(const std::vector<double>& v) {
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Both samples pooled and sorted, each value remembering its sample.
struct Pooled {
  double x;
  bool first;
};
std::vector<Pooled> pool(std::span<const double> a, std::span<const double> b) {
  std::vector<Pooled> all;
  all.reserve(a.size() + b.size());
  for (double x : a) all.push_back({x, true});
  for (double x : b) all.push_back({x, false});
  std::sort(all.begin(), all.end(), [](const Pooled& l, const Pooled& r) { return l.x < r.x; });
  return all;
}

// P(U >= k) for samples of sizes m and n without ties: the count of the C(m+n, m) equally
// likely arrangements whose U is at least k. Arrangements are built in rank order; an
// element of the first sample placed after `t - j` elements of the second adds t - j to U.
// Counts are positive sums only, so doubles keep their relative precision.
double exact_u_sf(std::size_t m, std::size_t n, std::size_t k) {
  if (m > n) std::swap(m, n);   // U's distribution is symmetric in the two sizes
  const std::size_t top = m * n;
  // ways[j][u]: arrangements of the first t elements holding j of the smaller sample, with U = u.
  std::vector<std::vector<double>> ways(m + 1, std::vector<double>(top + 1, 0.0));
  ways[0][0] = 1.0;
  for (std::size_t t = 0; t < m + n; ++t)
    for (std::size_t j = std::min(m, t + 1); j >= 1; --j) {
      const std::size_t add = t - (j - 1);   // elements of the larger sample placed before
      if (add > n) continue;                 // more of the larger sample than it has
      for (std::size_t u = top; u + 1 > add; --u) ways[j][u] += ways[j - 1][u - add];
    }
  const std::vector<double>& c = ways[m];
  double total = 0.0, tail = 0.0;
  for (std::size_t u = 0; u <= top; ++u) {
    total += c[u];
    if (u >= k) tail += c[u];
  }
  return tail / total;
}

}  // namespace

Summary summarise(std::span<const double> sample) {
  Summary s;
  s.n = sample.size();
  if (s.n == 0) return s;
  std::vector<double> v(sample.begin(), sample.end());
  std::sort(v.begin(), v.end());
  const eval::Moments m = eval::moments(v);
  s.mean = m.mean;
  s.sd = m.sd;
  s.median = median_of_sorted(v);
  s.min = v.front();
  s.max = v.back();
  return s;
}

TestResult welch_t_test(std::span<const double> a, std::span<const double> b) {
  if (a.size() < 2 || b.size() < 2) return undefined();
  const Summary sa = summarise(a);
  const Summary sb = summarise(b);
  const double va = sa.sd * sa.sd / static_cast<double>(sa.n);
  const double vb = sb.sd * sb.sd / static_cast<double>(sb.n);
  const double se2 = va + vb;
  if (!(se2 > 0.0) || !std::isfinite(se2)) return undefined();
  TestResult r;
  r.statistic = (sa.mean - sb.mean) / std::sqrt(se2);
  r.df = se2 * se2 / (va * va / static_cast<double>(sa.n - 1) + vb * vb / static_cast<double>(sb.n - 1));
  if (!std::isfinite(r.statistic) || !std::isfinite(r.df)) return undefined();
  const boost::math::students_t dist(r.df);
  r.p_value = std::min(1.0, 2.0 * boost::math::cdf(boost::math::complement(dist, std::fabs(r.statistic))));
  return r;
}

TestResult mann_whitney_u(std::span<const double> a, std::span<const double> b, UMethod method) {
  if (a.empty() || b.empty()) return undefined();
  const std::vector<Pooled> all = pool(a, b);
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
  TestResult r;
  r.statistic = rank_sum_a - n1 * (n1 + 1.0) / 2.0;
  const double u = std::max(r.statistic, n1 * n2 - r.statistic);   // the larger U
  const double cells = std::min(n1, n2) * (n1 + n2) * n1 * n2;
  const bool can_be_exact = ties == 0.0 && cells <= kMaxExactCells;
  const bool exact = can_be_exact && (method == UMethod::Exact ||
                                      (method == UMethod::Auto && (a.size() <= 8 || b.size() <= 8)));
  if (exact) {
    r.exact = true;
    r.p_value = std::min(1.0, 2.0 * exact_u_sf(a.size(), b.size(), static_cast<std::size_t>(u)));
    return r;
  }
  const double mu = n1 * n2 / 2.0;
  const double var = n1 * n2 / 12.0 * ((n + 1.0) - ties / (n * (n - 1.0)));
  if (!(var > 0.0)) return undefined();
  const double z = (u - mu - 0.5) / std::sqrt(var);
  const boost::math::normal_distribution<double> normal;
  r.p_value = std::min(1.0, 2.0 * boost::math::cdf(boost::math::complement(normal, z)));
  return r;
}

double vargha_delaney_a12(std::span<const double> a, std::span<const double> b) {
  if (a.empty() || b.empty()) return kNaN;
  const TestResult u = mann_whitney_u(a, b, UMethod::Asymptotic);
  // U of the first sample counts the pairs it wins, ties as half: A12 is its share.
  return (std::isnan(u.statistic) ? 0.5 * static_cast<double>(a.size() * b.size()) : u.statistic) /
         (static_cast<double>(a.size()) * static_cast<double>(b.size()));
}

TestResult brown_forsythe(std::span<const double> a, std::span<const double> b) {
  if (a.size() < 2 || b.size() < 2) return undefined();
  // Absolute deviations from each sample's median, then a one-way ANOVA of them.
  const auto deviations = [](std::span<const double> s) {
    std::vector<double> v(s.begin(), s.end());
    std::sort(v.begin(), v.end());
    const double med = median_of_sorted(v);
    for (double& x : v) x = std::fabs(x - med);
    return v;
  };
  const std::vector<double> za = deviations(a), zb = deviations(b);
  const Summary sa = summarise(za), sb = summarise(zb);
  const auto na = static_cast<double>(za.size()), nb = static_cast<double>(zb.size());
  const double grand = (sa.mean * na + sb.mean * nb) / (na + nb);
  const double between = na * (sa.mean - grand) * (sa.mean - grand) + nb * (sb.mean - grand) * (sb.mean - grand);
  const double within = (na - 1.0) * sa.sd * sa.sd + (nb - 1.0) * sb.sd * sb.sd;
  // Deviations equal within each sample (always so for two values) leave only rounding in
  // `within`: the statistic would be rounding noise divided into the between term.
  if (!(within > 1e-12 * (between + within)) || !std::isfinite(within)) return undefined();
  TestResult r;
  r.df = na + nb - 2.0;
  r.statistic = r.df * between / within;
  const boost::math::fisher_f dist(1.0, r.df);
  r.p_value = boost::math::cdf(boost::math::complement(dist, r.statistic));
  return r;
}

FisherResult fisher_exact(std::size_t successes_a, std::size_t failures_a, std::size_t successes_b,
                          std::size_t failures_b) {
  const std::size_t row_a = successes_a + failures_a, row_b = successes_b + failures_b;
  const std::size_t successes = successes_a + successes_b, failures = failures_a + failures_b;
  if (row_a == 0 || row_b == 0 || successes == 0 || failures == 0) return {kNaN, 1.0};
  FisherResult r;
  const auto ad = static_cast<double>(successes_a) * static_cast<double>(failures_b);
  const auto bc = static_cast<double>(failures_a) * static_cast<double>(successes_b);
  r.odds_ratio = bc > 0.0 ? ad / bc : std::numeric_limits<double>::infinity();
  // successes_a given the margins: of the row_a + row_b runs, `successes` succeeded; how many
  // of them fall in the first sample's row_a is hypergeometric.
  const boost::math::hypergeometric_distribution<double> h(static_cast<unsigned>(successes),
                                                            static_cast<unsigned>(row_a),
                                                            static_cast<unsigned>(row_a + row_b));
  const double observed =
      boost::math::pdf(h, static_cast<unsigned>(successes_a)) * (1.0 + kFisherRelativeTolerance);
  const std::size_t lo = row_a > failures ? row_a - failures : 0, hi = std::min(successes, row_a);
  double p = 0.0;
  bool any_more_probable = false;
  for (std::size_t k = lo; k <= hi; ++k) {
    const double pk = boost::math::pdf(h, static_cast<unsigned>(k));
    if (pk <= observed) p += pk;
    else any_more_probable = true;
  }
  // The most probable table has p 1, not a sum that rounds below it.
  r.p_value = any_more_probable ? std::min(1.0, p) : 1.0;
  return r;
}

TestResult censored_mann_whitney(std::span<const std::optional<double>> a, std::span<const std::optional<double>> b,
                                 double budget) {
  double top = budget;
  for (const auto* s : {&a, &b})
    for (const std::optional<double>& x : *s)
      if (x) top = std::max(top, *x);
  const auto censored = [top](std::span<const std::optional<double>> s) {
    std::vector<double> v;
    v.reserve(s.size());
    for (const std::optional<double>& x : s) v.push_back(x ? *x : top + 1.0);
    return v;
  };
  return mann_whitney_u(censored(a), censored(b));
}

}  // namespace esc::report
