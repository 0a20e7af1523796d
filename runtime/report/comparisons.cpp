#include "runtime/report/comparisons.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace esc::report {

std::vector<double> holm(std::span<const double> p) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (!std::isnan(p[i])) order.push_back(i);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t l, std::size_t r) { return p[l] < p[r]; });
  std::vector<double> adjusted(p.begin(), p.end());
  const std::size_t m = order.size();
  double running = 0.0;   // adjusted p-values never decrease along the sorted order
  for (std::size_t k = 0; k < m; ++k) {
    running = std::max(running, std::min(1.0, static_cast<double>(m - k) * p[order[k]]));
    adjusted[order[k]] = running;
  }
  return adjusted;
}

namespace {

// Values that differ only in their last bits (runs that all end the same way) have a spread
// of rounding: a ratio over it prints the noise (1e14), not a comparison.
constexpr double kRoundingSpread = 1e-12;

bool has_spread(const Summary& s) { return s.sd > kRoundingSpread * std::max(1.0, std::abs(s.mean)); }

}  // namespace

std::vector<Comparison> compare(std::span<const std::vector<double>> samples,
                                std::span<const std::pair<std::size_t, std::size_t>> pairs) {
  std::vector<Comparison> out;
  std::vector<double> welch_p, mw_p, spread_p;
  for (const auto& [i, j] : pairs) {
    Comparison c;
    c.a = i;
    c.b = j;
    c.welch = welch_t_test(samples[i], samples[j]);
    c.mann_whitney = mann_whitney_u(samples[i], samples[j]);
    c.a12 = vargha_delaney_a12(samples[i], samples[j]);
    c.spread = brown_forsythe(samples[i], samples[j]);
    const Summary a = summarise(samples[i]), b = summarise(samples[j]);
    c.sd_ratio = has_spread(b) && samples[i].size() > 1 ? a.sd / b.sd : std::numeric_limits<double>::quiet_NaN();
    welch_p.push_back(c.welch.p_value);
    mw_p.push_back(c.mann_whitney.p_value);
    spread_p.push_back(c.spread.p_value);
    out.push_back(c);
  }
  const std::vector<double> wh = holm(welch_p), mh = holm(mw_p), sh = holm(spread_p);
  for (std::size_t k = 0; k < out.size(); ++k) {
    out[k].welch_p_holm = wh[k];
    out[k].mann_whitney_p_holm = mh[k];
    out[k].spread_p_holm = sh[k];
  }
  return out;
}

std::vector<std::pair<std::size_t, std::size_t>> all_pairs(std::size_t count) {
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t i = 0; i < count; ++i)
    for (std::size_t j = i + 1; j < count; ++j) pairs.emplace_back(i, j);
  return pairs;
}

}  // namespace esc::report
