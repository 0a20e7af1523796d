#include "runtime/evo/gp/selection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace esc::evo::gp {

using namespace genome::tree;

namespace {
double key(double f) noexcept { return std::isnan(f) ? -std::numeric_limits<double>::infinity() : f; }
}  // namespace

bool better(const Individual& a, const Individual& b) noexcept {
  const double fa = key(a.fitness), fb = key(b.fitness);
  if (fa != fb) return fa > fb;
  return a.tree.size() < b.tree.size();
}

std::size_t tournament(std::span<const Individual> population, int size, Rng& rng) {
  std::size_t best = rng.below(population.size());
  for (int k = 1; k < size; ++k) {
    const std::size_t c = rng.below(population.size());
    if (better(population[c], population[best])) best = c;
  }
  return best;
}

std::vector<std::size_t> ranking(std::span<const Individual> population) {
  std::vector<std::size_t> order(population.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return better(population[a], population[b]);
  });
  return order;
}

}  // namespace esc::evo::gp
