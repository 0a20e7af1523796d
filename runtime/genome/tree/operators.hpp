#pragma once
// Variation operators on flat trees. Each takes its parent(s) by const reference and the
// Rng explicitly and returns a new tree that is well typed and within the limits whenever
// the parents are: a subtree is only ever replaced by one of the same type, and a move
// that would break a limit is never made. When no legal move exists the parent is
// returned unchanged (a copy).
#include <cstddef>
#include <optional>
#include <utility>

#include "runtime/core/rng.hpp"
#include "runtime/genome/tree/tree.hpp"

namespace esc::genome::tree {

struct Limits {
  int max_depth = 17;
  int max_size = 200;
};

// Replaces the subtree of `a` at node i with the subtree of `b` at node j (no checks).
[[nodiscard]] Tree splice(const Tree& a, std::size_t i, const Tree& b, std::size_t j);

// Crossover points (i in a, j in b) of the same type whose splice fits the limits, or none.
// i is an internal node with probability `internal_bias` when a has any (Koza's 90/10),
// j is uniform among the legal points of b; up to 8 choices of i are tried.
[[nodiscard]] std::optional<std::pair<std::size_t, std::size_t>> crossover_points(
    const Tree& a, const Tree& b, const PrimitiveSet& set, Limits limits, double internal_bias,
    Rng& rng);

// Subtree crossover: the child is `a` with one subtree replaced by a same-typed subtree of b.
[[nodiscard]] Tree crossover(const Tree& a, const Tree& b, const PrimitiveSet& set, Limits limits,
                             double internal_bias, Rng& rng);

// Subtree mutation: a random node is replaced by a random grown tree of its type, of depth
// at most `new_depth` (and within the limits).
[[nodiscard]] Tree subtree_mutation(const Tree& a, const PrimitiveSet& set, Limits limits,
                                    int new_depth, Rng& rng);

// Point mutation of one random node: an ERC value moves by N(0, erc_sigma * (hi - lo));
// any other node becomes another primitive of the same signature (a terminal of the same
// type, possibly a fresh ERC; a function with the same argument and result types), its
// arguments kept. A node with no alternative is left as is.
[[nodiscard]] Tree point_mutation(const Tree& a, const PrimitiveSet& set, double erc_sigma, Rng& rng);

// Hoist mutation: a random subtree S is replaced by a random proper subtree of S of the
// same type. The tree shrinks (bloat control); returned unchanged when no node has a
// descendant of its own type.
[[nodiscard]] Tree hoist_mutation(const Tree& a, const PrimitiveSet& set, Rng& rng);

}  // namespace esc::genome::tree
