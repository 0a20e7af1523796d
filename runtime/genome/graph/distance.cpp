#include "runtime/genome/graph/distance.hpp"

#include <cmath>

namespace esc::genome::graph {

Alignment align(const Graph& a, const Graph& b) {
  Alignment r;
  std::size_t i = 0, j = 0;
  while (i < a.links.size() || j < b.links.size()) {
    if (i == a.links.size()) {
      ++j;
      ++r.excess;
    } else if (j == b.links.size()) {
      ++i;
      ++r.excess;
    } else if (a.links[i].innovation == b.links[j].innovation) {
      r.weight_difference += std::abs(a.links[i++].weight - b.links[j++].weight);
      ++r.matching;
    } else {
      (a.links[i].innovation < b.links[j].innovation ? i : j)++;
      ++r.disjoint;
    }
  }
  return r;
}

double compatibility(const Graph& a, const Graph& b, const Coefficients& c) {
  const Alignment r = align(a, b);
  const double mean = r.matching == 0 ? 0.0 : r.weight_difference / static_cast<double>(r.matching);
  return c.excess * static_cast<double>(r.excess) + c.disjoint * static_cast<double>(r.disjoint) + c.weight * mean;
}

}  // namespace esc::genome::graph
