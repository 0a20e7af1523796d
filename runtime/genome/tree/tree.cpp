#include "runtime/genome/tree/tree.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace esc::genome::tree {

Node make_node(const PrimitiveSet& set, PrimitiveId id, double value) noexcept {
  const Primitive& p = set[id];
  Node n;
  n.prim = id;
  n.arity = p.arity;
  n.type = p.result;
  n.length = 1;
  n.value = p.kind == Kind::Constant ? p.value : value;
  return n;
}

std::array<std::size_t, kMaxArity> children(const Tree& t, std::size_t i) noexcept {
  std::array<std::size_t, kMaxArity> c{};
  std::size_t j = i;  // one past the end of the next argument's subtree
  for (std::size_t k = t.nodes[i].arity; k-- > 0;) {
    c[k] = j - 1;
    j -= t.nodes[j - 1].length;
  }
  return c;
}

bool update_lengths(Tree& t) noexcept {
  // A stack of subtree lengths; each node consumes `arity` of them.
  std::vector<std::uint32_t> stack;
  stack.reserve(t.nodes.size());
  for (Node& n : t.nodes) {
    if (stack.size() < n.arity) return false;
    std::uint32_t len = 1;
    for (std::size_t k = 0; k < n.arity; ++k) {
      len += stack.back();
      stack.pop_back();
    }
    n.length = len;
    stack.push_back(len);
  }
  return stack.size() == 1;
}

std::vector<int> subtree_depths(const Tree& t) {
  std::vector<int> d(t.size(), 1);
  for (std::size_t i = 0; i < t.size(); ++i) {
    const auto c = children(t, i);
    for (std::size_t k = 0; k < t.nodes[i].arity; ++k) d[i] = std::max(d[i], d[c[k]] + 1);
  }
  return d;
}

int depth(const Tree& t) noexcept {
  if (t.empty()) return 0;
  // Walk postfix with a stack of depths, no allocation beyond one small vector.
  int deepest = 0;
  std::vector<int> stack;
  stack.reserve(64);
  for (const Node& n : t.nodes) {
    int d = 1;
    for (std::size_t k = 0; k < n.arity; ++k) {
      d = std::max(d, stack.back() + 1);
      stack.pop_back();
    }
    stack.push_back(d);
    deepest = std::max(deepest, d);
  }
  return deepest;
}

std::vector<int> levels(const Tree& t) {
  std::vector<int> lv(t.size(), 1);
  for (std::size_t i = t.size(); i-- > 0;) {  // parents come after their children
    const auto c = children(t, i);
    for (std::size_t k = 0; k < t.nodes[i].arity; ++k) lv[c[k]] = lv[i] + 1;
  }
  return lv;
}

std::string check(const Tree& t, const PrimitiveSet& set, Type root) {
  if (t.empty()) return "the tree is empty";
  // Stack of (type, length) of complete subtrees.
  struct Item {
    Type type;
    std::uint32_t length;
  };
  std::vector<Item> stack;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const Node& n = t.nodes[i];
    if (n.prim >= set.size()) return fmt::format("node {}: primitive id {} out of range", i, n.prim);
    const Primitive& p = set[n.prim];
    if (n.arity != p.arity)
      return fmt::format("node {} (`{}`): arity {}, primitive has {}", i, p.name, n.arity, p.arity);
    if (n.type != p.result)
      return fmt::format("node {} (`{}`): cached type {}, primitive returns {}", i, p.name,
                         name_of(n.type), name_of(p.result));
    if (stack.size() < n.arity) return fmt::format("node {} (`{}`): missing arguments", i, p.name);
    std::uint32_t len = 1;
    for (std::size_t k = n.arity; k-- > 0;) {
      const Item a = stack.back();
      stack.pop_back();
      if (a.type != p.args[k])
        return fmt::format("node {} (`{}`): argument {} is a {}, expected a {}", i, p.name, k,
                           name_of(a.type), name_of(p.args[k]));
      len += a.length;
    }
    if (n.length != len)
      return fmt::format("node {} (`{}`): length {}, subtree has {} nodes", i, p.name, n.length, len);
    if (p.kind == Kind::Erc && !std::isfinite(n.value))
      return fmt::format("node {}: random constant {} is not finite", i, n.value);
    if (p.kind == Kind::Constant && n.value != p.value)
      return fmt::format("node {}: constant `{}` holds {}", i, p.name, n.value);
    stack.push_back({p.result, len});
  }
  if (stack.size() != 1) return fmt::format("{} trees instead of one", stack.size());
  if (stack.back().type != root)
    return fmt::format("the root is a {}, expected a {}", name_of(stack.back().type), name_of(root));
  return {};
}

}  // namespace esc::genome::tree
