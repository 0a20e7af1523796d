#include "runtime/evo/pareto/selection.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

namespace esc::evo {

Ranking rank_and_crowd(const ObjectiveRows& f) {
  Ranking r;
  r.rank.assign(f.size(), 0);
  r.crowding.assign(f.size(), 0.0);
  const auto fronts = nondominated_fronts(f);
  for (std::size_t k = 0; k < fronts.size(); ++k) {
    const std::vector<double> d = crowding_distance(f, fronts[k]);
    for (std::size_t i = 0; i < fronts[k].size(); ++i) {
      r.rank[fronts[k][i]] = k;
      r.crowding[fronts[k][i]] = d[i];
    }
  }
  return r;
}

bool crowded_before(const Ranking& r, std::size_t a, std::size_t b) noexcept {
  if (r.rank[a] != r.rank[b]) return r.rank[a] < r.rank[b];
  if (r.crowding[a] != r.crowding[b]) return r.crowding[a] > r.crowding[b];
  return a < b;
}

std::size_t crowded_tournament(const Ranking& r, std::size_t a, std::size_t b) noexcept {
  return crowded_before(r, b, a) ? b : a;
}

std::vector<std::size_t> select_survivors(const Ranking& r, std::size_t n) {
  if (r.rank.size() != r.crowding.size())
    throw std::invalid_argument("select_survivors: " + std::to_string(r.rank.size()) + " ranks but " +
                                std::to_string(r.crowding.size()) + " crowding distances");
  if (n > r.rank.size())
    throw std::invalid_argument("select_survivors: cannot keep " + std::to_string(n) + " of " +
                                std::to_string(r.rank.size()) + " points");
  std::vector<std::size_t> order(r.rank.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(n), order.end(),
                    [&](std::size_t a, std::size_t b) { return crowded_before(r, a, b); });
  order.resize(n);
  std::sort(order.begin(), order.end());
  return order;
}

std::vector<std::size_t> select_survivors(const ObjectiveRows& f, std::size_t n) {
  return select_survivors(rank_and_crowd(f), n);
}

}  // namespace esc::evo
