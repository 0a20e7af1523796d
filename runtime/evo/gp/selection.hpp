#pragma once
// Tournament selection with lexicographic parsimony pressure (Luke & Panait 2002): the
// fitter individual wins, and of two equally fit ones the smaller tree wins. Fitness is
// maximised; NaN fitness ranks below every number.
#include <cstddef>
#include <span>
#include <vector>

#include "runtime/core/rng.hpp"
#include "runtime/genome/tree/tree.hpp"

namespace esc::evo::gp {

struct Individual {
  genome::tree::Tree tree;
  double fitness = 0.0;
};

// Strictly better: higher fitness, or equal fitness and fewer nodes.
[[nodiscard]] bool better(const Individual& a, const Individual& b) noexcept;

// Index of the winner of `size` contestants drawn uniformly with replacement; of equally
// good contestants the first drawn wins. Precondition: population non-empty, size >= 1.
[[nodiscard]] std::size_t tournament(std::span<const Individual> population, int size, Rng& rng);

// Indices of the population from best to worst by `better`, ties in index order.
[[nodiscard]] std::vector<std::size_t> ranking(std::span<const Individual> population);

}  // namespace esc::evo::gp
