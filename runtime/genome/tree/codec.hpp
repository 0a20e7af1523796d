#pragma once
// Trees as flat vectors of doubles, the form results store them in (a run's best tree is
// its "genome", a population is what a run resumes from): per node in postfix order, the
// primitive id, then the node's value (an ERC's or a constant's; 0 otherwise). Ids below
// 2^16 and every double are exact, so the round trip is lossless. Arities, types and
// lengths come back from the primitive set, so an encoded tree means something only with
// the set it was built over (the same script).
#include <span>
#include <vector>

#include "runtime/genome/tree/tree.hpp"

namespace esc::genome::tree {

inline constexpr std::size_t kCodedNodeWidth = 2;   // doubles per node

// Appends the tree's 2 x size() doubles to `out`.
void encode(const Tree& tree, std::vector<double>& out);
[[nodiscard]] std::vector<double> encode(const Tree& tree);

// Throws std::invalid_argument if `genes` is not a well-typed tree of the set's root type
// (an odd length, an id outside the set, a non-integral id, arities that do not form one
// tree, a wrong type, a value that is not finite).
[[nodiscard]] Tree decode(std::span<const double> genes, const PrimitiveSet& set);

}  // namespace esc::genome::tree
