#pragma once
// How trees are varied: grown at first (ramped half-and-half), crossed, mutated, and how
// large they may grow. These belong to the tree kind, not to GP: the experiment gives them
// in `evolve gp(...)` (its historic place, docs/language.md), and GP breeds with them as
// every algorithm that evolves trees (NSGA-II, novelty search, MAP-Elites) varies with them.
#include "runtime/core/rng.hpp"
#include "runtime/genome/tree/operators.hpp"

namespace esc::genome::tree {

struct TreeOperators {
  // Operator probabilities per offspring; what is left is reproduction (a copy of the winner).
  double crossover = 0.8;
  double subtree_mutation = 0.05;
  double point_mutation = 0.05;
  double hoist_mutation = 0.05;
  int max_depth = 12;              // nodes from root to deepest leaf (a terminal has depth 1)
  int max_size = 100;              // nodes
  int init_min_depth = 2;          // ramped half-and-half depth range
  int init_max_depth = 6;
  int mutation_depth = 4;          // depth of the subtrees grown by subtree mutation
  double internal_bias = 0.9;      // crossover picks an internal node this often (Koza)
  double erc_sigma = 0.1;          // point mutation of an ERC: N(0, erc_sigma * (hi - lo)); at
                                   // most kMaxErcSigma (as the ES's kMaxStepSize)

  // Deepest trees the flat evaluator can run (its stack has FlatProgram::kMaxStack slots).
  static constexpr int kMaxDepthLimit = 40;
  static constexpr double kMaxErcSigma = 1e3;

  [[nodiscard]] Limits limits() const noexcept { return {max_depth, max_size}; }
};

// Throws std::invalid_argument ("genetic programming: ...", naming the setting) when `ops`
// cannot vary trees of `set`: probabilities outside [0, 1] or summing above 1, max_depth
// below the shallowest tree of the root type or above kMaxDepthLimit, max_size below the
// smallest tree, init depths out of order, ...
void check_operators(const TreeOperators& ops, const PrimitiveSet& set);

// The mutation mix on `a` for a uniform draw u: subtree mutation when u < edge +
// subtree_mutation, point mutation below that plus point_mutation, hoist mutation below that
// plus hoist_mutation, else a copy. `edge` is the part of [0, 1) taken before the mutations
// (GP's crossover), so that every algorithm that mutates trees applies exactly the same
// operators and probabilities.
[[nodiscard]] Tree mutate(const Tree& a, const TreeOperators& ops, const PrimitiveSet& set, double u, double edge,
                          Rng& rng);

}  // namespace esc::genome::tree
