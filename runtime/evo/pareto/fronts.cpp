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

// The points without NaN in lexicographic order of their objectives: a point's dominators
// all come before it (no worse in every objective, better in one), equal points side by side.
std::vector<std::size_t> lexicographic(const ObjectiveRows& f, std::vector<std::size_t> points) {
  std::sort(points.begin(), points.end(), [&](std::size_t a, std::size_t b) {
    return std::lexicographical_compare(f[a].begin(), f[a].end(), f[b].begin(), f[b].end());
  });
  return points;
}

// Each point's front (0: dominated by none), indexed like f. Deb's front of a point is the
// length of the longest chain of points dominating one another that ends in it, so one pass
// in lexicographic order finds it from the points before it alone. O(M N^2) time like Deb's
// sort, but O(N) memory where his lists of dominated points hold up to N^2 / 4 indices (a
// population of 20,000 held 1.5 GB in them).
std::vector<std::size_t> front_numbers(const ObjectiveRows& f, const std::vector<std::size_t>& points) {
  std::vector<std::size_t> front(f.size(), 0);
  const std::vector<std::size_t> order = lexicographic(f, points);
  for (std::size_t b = 0; b < order.size(); ++b)
    for (std::size_t a = 0; a < b; ++a)
      if (front[order[a]] + 1 > front[order[b]] && dominates(f[order[a]], f[order[b]]))
        front[order[b]] = front[order[a]] + 1;
  return front;
}

// The same for two objectives in O(N log N) (Jensen, IEEE TEC 7(5), 2003): in lexicographic
// order each front's members run down in the second objective, so its last member is the
// only one that can dominate the next point, and whether a front dominates it is true for
// the first fronts and false after them (a member of front k + 1 is dominated by one of
// front k): a binary search over the fronts' last members finds the point's front.
std::vector<std::size_t> two_objective_fronts(const ObjectiveRows& f, const std::vector<std::size_t>& points) {
  std::vector<std::size_t> front(f.size(), 0);
  std::vector<std::size_t> last;   // per front, its member latest in lexicographic order
  for (const std::size_t p : lexicographic(f, points)) {
    const auto dominated_by = [&](std::size_t q) { return dominates(f[q], f[p]); };
    const auto k = std::partition_point(last.begin(), last.end(), dominated_by);
    front[p] = static_cast<std::size_t>(k - last.begin());
    if (k == last.end())
      last.push_back(p);
    else
      *k = p;
  }
  return front;
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

  const std::vector<std::size_t> front = m == 2 ? two_objective_fronts(f, measured) : front_numbers(f, measured);
  std::vector<std::vector<std::size_t>> fronts;
  for (const std::size_t p : measured) {
    if (front[p] >= fronts.size()) fronts.resize(front[p] + 1);
    fronts[front[p]].push_back(p);   // ascending, as `measured` is
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
