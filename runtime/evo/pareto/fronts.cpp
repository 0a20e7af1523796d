#include "runtime/evo/pareto/fronts.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace esc::evo {

namespace {

bool has_nan(std::span<const double> v) {
  return std::any_of(v.begin(), v.end(), [](double x) { return std::isnan(x); });
}

}  // namespace

bool dominates(std::span<const double> a, std::span<const double> b) noexcept {
  if (a.size() != b.size() || has_nan(a) || has_nan(b)) return false;
  bool better = false;
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (a[k] > b[k]) return false;
    if (a[k] < b[k]) better = true;
  }
  return better;
}

std::vector<std::vector<std::size_t>> nondominated_fronts(const ObjectiveRows& f) {
  if (f.empty()) return {};
  const std::size_t m = f.front().size();
  for (std::size_t i = 0; i < f.size(); ++i)
    if (f[i].size() != m || m == 0)
      throw std::invalid_argument("nondominated_fronts: point " + std::to_string(i) + " has " +
                                  std::to_string(f[i].size()) + " objectives, point 0 has " + std::to_string(m) +
                                  " (at least 1, all alike)");

  std::vector<std::size_t> measured, unmeasured;
  for (std::size_t i = 0; i < f.size(); ++i) (has_nan(f[i]) ? unmeasured : measured).push_back(i);

  // S_p (the points p dominates) and n_p (how many dominate p), over each pair once.
  std::vector<std::vector<std::size_t>> dominated(f.size());
  std::vector<std::size_t> dominators(f.size(), 0);
  for (std::size_t a = 0; a < measured.size(); ++a) {
    for (std::size_t b = a + 1; b < measured.size(); ++b) {
      const std::size_t p = measured[a], q = measured[b];
      if (dominates(f[p], f[q])) {
        dominated[p].push_back(q);
        ++dominators[q];
      } else if (dominates(f[q], f[p])) {
        dominated[q].push_back(p);
        ++dominators[p];
      }
    }
  }

  std::vector<std::vector<std::size_t>> fronts;
  std::vector<std::size_t> current;
  for (const std::size_t p : measured)
    if (dominators[p] == 0) current.push_back(p);
  while (!current.empty()) {
    std::vector<std::size_t> next;
    for (const std::size_t p : current)
      for (const std::size_t q : dominated[p])
        if (--dominators[q] == 0) next.push_back(q);
    std::sort(next.begin(), next.end());
    fronts.push_back(std::move(current));
    current = std::move(next);
  }
  if (!unmeasured.empty()) fronts.push_back(std::move(unmeasured));
  return fronts;
}

std::vector<double> crowding_distance(const ObjectiveRows& f, std::span<const std::size_t> front) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::vector<double> distance(front.size(), 0.0);
  std::vector<std::size_t> order;  // positions in `front` of the points without NaN
  for (std::size_t pos = 0; pos < front.size(); ++pos) {
    if (front[pos] >= f.size())
      throw std::invalid_argument("crowding_distance: index " + std::to_string(front[pos]) + " outside the " +
                                  std::to_string(f.size()) + " points");
    if (f[front[pos]].size() != f[front.front()].size() || f[front[pos]].empty())
      throw std::invalid_argument("crowding_distance: the points differ in their number of objectives");
    if (!has_nan(f[front[pos]])) order.push_back(pos);
  }
  if (order.size() <= 2) {
    for (const std::size_t pos : order) distance[pos] = kInf;
    return distance;
  }

  const std::size_t m = f[front[order.front()]].size();
  for (std::size_t k = 0; k < m; ++k) {
    const auto value = [&](std::size_t pos) { return f[front[pos]][k]; };
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return value(a) < value(b) || (value(a) == value(b) && front[a] < front[b]);
    });
    distance[order.front()] = kInf;
    distance[order.back()] = kInf;
    const double range = value(order.back()) - value(order.front());
    if (!(range > 0.0) || !std::isfinite(range)) continue;
    for (std::size_t i = 1; i + 1 < order.size(); ++i)
      distance[order[i]] += (value(order[i + 1]) - value(order[i - 1])) / range;
  }
  return distance;
}

}  // namespace esc::evo
