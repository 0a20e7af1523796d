#include "runtime/genome/tree/tree_operators.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace esc::genome::tree {

namespace {

void require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument("genetic programming: " + message);
}

void probability(double p, const char* name) {
  require(std::isfinite(p) && p >= 0.0 && p <= 1.0,
          fmt::format("{} must be a probability in [0, 1], got {}", name, p));
}

}  // namespace

void check_operators(const TreeOperators& s, const PrimitiveSet& set) {
  const Type root = set.root();
  probability(s.crossover, "crossover");
  probability(s.subtree_mutation, "subtree_mutation");
  probability(s.point_mutation, "point_mutation");
  probability(s.hoist_mutation, "hoist_mutation");
  probability(s.internal_bias, "internal_bias");
  const double sum = s.crossover + s.subtree_mutation + s.point_mutation + s.hoist_mutation;
  require(sum <= 1.0 + 1e-12,
          fmt::format("crossover and mutation probabilities sum to {}, above 1", sum));
  require(s.max_depth >= set.min_depth(root) && s.max_depth <= TreeOperators::kMaxDepthLimit,
          fmt::format("max_depth must be in [{}, {}] (the shallowest {} tree has depth {}), got {}",
                      set.min_depth(root), TreeOperators::kMaxDepthLimit, name_of(root),
                      set.min_depth(root), s.max_depth));
  require(s.max_size >= set.min_size(root),
          fmt::format("max_size must be at least {} (the smallest {} tree), got {}",
                      set.min_size(root), name_of(root), s.max_size));
  require(s.init_min_depth >= 1 && s.init_min_depth <= s.init_max_depth &&
              s.init_max_depth <= s.max_depth,
          fmt::format("init depths must satisfy 1 <= init_min_depth ({}) <= init_max_depth ({}) "
                      "<= max_depth ({})",
                      s.init_min_depth, s.init_max_depth, s.max_depth));
  require(s.mutation_depth >= 1,
          fmt::format("mutation_depth must be at least 1, got {}", s.mutation_depth));
  require(s.erc_sigma >= 0.0 && s.erc_sigma <= TreeOperators::kMaxErcSigma,
          fmt::format("erc_sigma must be in [0, 1000], got {}", s.erc_sigma));
}

Tree mutate(const Tree& a, const TreeOperators& s, const PrimitiveSet& set, double u, double edge, Rng& rng) {
  if (u < (edge += s.subtree_mutation)) return subtree_mutation(a, set, s.limits(), s.mutation_depth, rng);
  if (u < (edge += s.point_mutation)) return point_mutation(a, set, s.erc_sigma, rng);
  if (u < (edge += s.hoist_mutation)) return hoist_mutation(a, set, rng);
  return a;
}

}  // namespace esc::genome::tree
