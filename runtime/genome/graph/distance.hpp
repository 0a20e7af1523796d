#pragma once
// NEAT's compatibility distance (the paper's equation 1, delta = c1 E / N + c2 D / N + c3 W),
// as NEAT C++'s Genome::compatibility computes it: with N = 1, the counts themselves (the
// paper sets N = 1 for genomes of fewer than 20 genes, and the code never normalises), and
// W the mean absolute weight difference of the matching links (0 when none match, where
// the code divides by zero).
#include <cstddef>

#include "runtime/genome/graph/graph.hpp"

namespace esc::genome::graph {

struct Alignment {
  std::size_t matching = 0;
  std::size_t disjoint = 0;   // inside the other's innovation range
  std::size_t excess = 0;     // beyond it
  double weight_difference = 0.0;   // summed |w_a - w_b| over matching links
};

[[nodiscard]] Alignment align(const Graph& a, const Graph& b);

struct Coefficients {
  double excess = 1.0;     // c1
  double disjoint = 1.0;   // c2
  double weight = 0.4;     // c3
};

[[nodiscard]] double compatibility(const Graph& a, const Graph& b, const Coefficients& c);

}  // namespace esc::genome::graph
