#include "runtime/evo/gp/gp.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "runtime/genome/tree/init.hpp"

namespace esc::evo::gp {

using namespace genome::tree;

namespace {

void require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument("genetic programming: " + message);
}

}  // namespace

GeneticProgramming::GeneticProgramming(const GpSettings& settings, PrimitiveSet set)
    : s_(settings), set_(std::move(set)) {
  require(s_.population >= 1, fmt::format("population must be at least 1, got {}", s_.population));
  require(s_.generations >= 0, fmt::format("generations must be non-negative, got {}", s_.generations));
  require(s_.tournament >= 1, fmt::format("tournament size must be at least 1, got {}", s_.tournament));
  require(s_.elitism >= 0 && s_.elitism <= s_.population,
          fmt::format("elitism must be in [0, population ({})], got {}", s_.population, s_.elitism));
  check_operators(s_, set_);
}

std::vector<Individual> GeneticProgramming::initial(Rng& rng) const {
  std::vector<Tree> trees =
      ramped_half_and_half(set_, static_cast<std::size_t>(s_.population), s_.init_min_depth,
                           s_.init_max_depth, s_.max_size, rng);
  std::vector<Individual> pop(trees.size());
  for (std::size_t i = 0; i < trees.size(); ++i) pop[i].tree = std::move(trees[i]);
  return pop;
}

std::size_t GeneticProgramming::select(std::span<const Individual> population, Rng& rng) const {
  require(!population.empty(), "selection needs a non-empty population");
  return tournament(population, s_.tournament, rng);
}

Individual GeneticProgramming::offspring(std::span<const Individual> population,
                                         std::uint64_t base, std::size_t i) const {
  Rng rng(base, {static_cast<std::uint64_t>(i)});
  const Tree& a = population[tournament(population, s_.tournament, rng)].tree;
  const double u = rng.uniform();
  const double edge = s_.crossover;
  Individual child;
  if (u < edge) {
    const Tree& b = population[tournament(population, s_.tournament, rng)].tree;
    child.tree = crossover(a, b, set_, limits(), s_.internal_bias, rng);
  } else {
    child.tree = mutate(a, s_, set_, u, edge, rng);
  }
  return child;
}

std::vector<Individual> GeneticProgramming::breed(std::span<const Individual> population,
                                                  Rng& rng) const {
  require(!population.empty(), "breed needs a non-empty population");
  const std::uint64_t base = rng.next();
  const auto n = static_cast<std::size_t>(s_.population);
  std::vector<Individual> next;
  next.reserve(n);
  const std::vector<std::size_t> order = ranking(population);
  for (std::size_t k = 0; k < static_cast<std::size_t>(s_.elitism) && k < order.size(); ++k)
    next.push_back(population[order[k]]);
  for (std::size_t i = next.size(); i < n; ++i) next.push_back(offspring(population, base, i));
  return next;
}

}  // namespace esc::evo::gp
