#pragma once
// Random trees: grow, full and ramped half-and-half (Koza), strongly typed. At each node
// only primitives that can still finish within the remaining depth are drawn (the
// PrimitiveSet knows the shallowest tree of each primitive), so generation always ends
// and never produces an ill-typed tree. A depth below the shallowest possible tree of the
// type is raised to it.
#include <cstddef>
#include <vector>

#include "runtime/core/rng.hpp"
#include "runtime/genome/tree/tree.hpp"

namespace esc::genome::tree {

// Grow: any primitive that fits the remaining depth, uniformly.
[[nodiscard]] Tree grow(const PrimitiveSet& set, Type type, int max_depth, Rng& rng);
// Full: non-terminals until the depth is reached (where the types allow), then terminals.
[[nodiscard]] Tree full(const PrimitiveSet& set, Type type, int depth, Rng& rng);
// The smallest tree of `type` (deterministic but for ERC values).
[[nodiscard]] Tree smallest(const PrimitiveSet& set, Type type, Rng& rng);

// `count` trees of the set's root type; tree i has depth limit min_depth + i mod (range)
// and alternates full / grow. A tree over max_size is drawn again (up to 20 times, then
// at ever smaller depth, at last the smallest tree), so every tree fits max_size when
// max_size >= set.min_size(root).
[[nodiscard]] std::vector<Tree> ramped_half_and_half(const PrimitiveSet& set, std::size_t count,
                                                     int min_depth, int max_depth, int max_size,
                                                     Rng& rng);

// Appends a random subtree of `type` in postfix order to `out` (lengths set). Used by
// subtree mutation.
void append_random(const PrimitiveSet& set, Type type, int max_depth, bool full, Rng& rng,
                   std::vector<Node>& out);

// A fresh value for an ERC primitive: uniform in [lo, hi].
[[nodiscard]] double draw_erc(const Primitive& p, Rng& rng) noexcept;

}  // namespace esc::genome::tree
