#include "runtime/evo/gp/gp.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "runtime/evo/gp/init.hpp"

namespace esc::evo::gp {

namespace {

void require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument("genetic programming: " + message);
}

void probability(double p, const char* name) {
  require(std::isfinite(p) && p >= 0.0 && p <= 1.0,
          fmt::format("{} must be a probability in [0, 1], got {}", name, p));
}

}  // namespace

GeneticProgramming::GeneticProgramming(const GpSettings& settings, PrimitiveSet set)
    : s_(settings), set_(std::move(set)) {
  const Type root = set_.root();
  require(s_.population >= 1, fmt::format("population must be at least 1, got {}", s_.population));
  require(s_.generations >= 0, fmt::format("generations must be non-negative, got {}", s_.generations));
  require(s_.tournament >= 1, fmt::format("tournament size must be at least 1, got {}", s_.tournament));
  require(s_.elitism >= 0 && s_.elitism <= s_.population,
          fmt::format("elitism must be in [0, population ({})], got {}", s_.population, s_.elitism));
  probability(s_.crossover, "crossover");
  probability(s_.subtree_mutation, "subtree_mutation");
  probability(s_.point_mutation, "point_mutation");
  probability(s_.hoist_mutation, "hoist_mutation");
  probability(s_.internal_bias, "internal_bias");
  const double sum = s_.crossover + s_.subtree_mutation + s_.point_mutation + s_.hoist_mutation;
  require(sum <= 1.0 + 1e-12,
          fmt::format("crossover and mutation probabilities sum to {}, above 1", sum));
  require(s_.max_depth >= set_.min_depth(root) && s_.max_depth <= GpSettings::kMaxDepthLimit,
          fmt::format("max_depth must be in [{}, {}] (the shallowest {} tree has depth {}), got {}",
                      set_.min_depth(root), GpSettings::kMaxDepthLimit, name_of(root),
                      set_.min_depth(root), s_.max_depth));
  require(s_.max_size >= set_.min_size(root),
          fmt::format("max_size must be at least {} (the smallest {} tree), got {}",
                      set_.min_size(root), name_of(root), s_.max_size));
  require(s_.init_min_depth >= 1 && s_.init_min_depth <= s_.init_max_depth &&
              s_.init_max_depth <= s_.max_depth,
          fmt::format("init depths must satisfy 1 <= init_min_depth ({}) <= init_max_depth ({}) "
                      "<= max_depth ({})",
                      s_.init_min_depth, s_.init_max_depth, s_.max_depth));
  require(s_.mutation_depth >= 1,
          fmt::format("mutation_depth must be at least 1, got {}", s_.mutation_depth));
  require(s_.erc_sigma >= 0.0 && s_.erc_sigma <= GpSettings::kMaxErcSigma,
          fmt::format("erc_sigma must be in [0, 1000], got {}", s_.erc_sigma));
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
    child.tree = mutate(a, u, edge, rng);
  }
  return child;
}

Tree GeneticProgramming::mutate(const Tree& a, double u, double edge, Rng& rng) const {
  if (u < (edge += s_.subtree_mutation)) return subtree_mutation(a, set_, limits(), s_.mutation_depth, rng);
  if (u < (edge += s_.point_mutation)) return point_mutation(a, set_, s_.erc_sigma, rng);
  if (u < (edge += s_.hoist_mutation)) return hoist_mutation(a, set_, rng);
  return a;
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
