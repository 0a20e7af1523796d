#pragma once
// A GP tree as one flat vector of nodes in postfix order (Operon's layout): every node
// carries its arity and the length of its subtree (itself included), so the subtree of
// node i is the contiguous range [i + 1 - length, i + 1), its last argument sits at i - 1
// and each earlier argument just before the subtree of the next. Crossover is a splice
// and copying a tree is copying a vector. The root is the last node.
//
// Depth counts nodes: a lone terminal has depth 1, wheels(ir[0], 0.5) has depth 2.
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "runtime/genome/tree/primitive_set.hpp"

namespace esc::genome::tree {

struct Node {
  PrimitiveId prim = 0;
  std::uint8_t arity = 0;
  Type type = Type::Number;    // the primitive's result type, cached
  std::uint32_t length = 1;    // nodes in this subtree, itself included
  double value = 0.0;          // ERC and constant value (0 otherwise)

  friend bool operator==(const Node&, const Node&) = default;
};

struct Tree {
  std::vector<Node> nodes;

  [[nodiscard]] std::size_t size() const noexcept { return nodes.size(); }
  [[nodiscard]] bool empty() const noexcept { return nodes.empty(); }
  [[nodiscard]] std::size_t root() const noexcept { return nodes.size() - 1; }
  // First index of the subtree rooted at i.
  [[nodiscard]] std::size_t begin_of(std::size_t i) const noexcept {
    return i + 1 - nodes[i].length;
  }
  friend bool operator==(const Tree&, const Tree&) = default;
};

// A node built from primitive `id` of `set` (value: for ERCs and constants; length 1 until
// the tree's lengths are recomputed).
[[nodiscard]] Node make_node(const PrimitiveSet& set, PrimitiveId id, double value = 0.0) noexcept;

// Indices of the arguments of node i, in argument order; the count is nodes[i].arity.
[[nodiscard]] std::array<std::size_t, kMaxArity> children(const Tree& t, std::size_t i) noexcept;

// Recomputes every length from the arities; returns false if the arities do not form one
// tree.
bool update_lengths(Tree& t) noexcept;

[[nodiscard]] int depth(const Tree& t) noexcept;
// Depth of each node's subtree (1 for a terminal).
[[nodiscard]] std::vector<int> subtree_depths(const Tree& t);
// Level of each node: 1 for the root, 2 for its arguments, ...
[[nodiscard]] std::vector<int> levels(const Tree& t);

// Empty if `t` is a well-formed, well-typed tree of `root` type over `set` (primitive ids in
// range, arities, cached types and lengths consistent with the primitives, each argument of
// the type its primitive expects, ERC values finite); else a sentence saying what is wrong.
[[nodiscard]] std::string check(const Tree& t, const PrimitiveSet& set, Type root);
[[nodiscard]] inline bool well_typed(const Tree& t, const PrimitiveSet& set, Type root) {
  return check(t, set, root).empty();
}

}  // namespace esc::genome::tree
