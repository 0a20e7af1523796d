#include "runtime/genome/tree/operators.hpp"

#include <cmath>
#include <vector>

#include "runtime/genome/tree/init.hpp"

namespace esc::genome::tree {

namespace {

// A random node: internal with probability `internal_bias` when there are internal nodes.
std::size_t pick_point(const Tree& t, double internal_bias, Rng& rng) {
  std::size_t internal = 0;
  for (const Node& n : t.nodes) internal += n.arity > 0 ? 1 : 0;
  const std::size_t leaves = t.size() - internal;
  const bool want_internal = internal > 0 && (leaves == 0 || rng.uniform() < internal_bias);
  std::size_t k = rng.below(want_internal ? internal : leaves);
  for (std::size_t i = 0; i < t.size(); ++i)
    if ((t.nodes[i].arity > 0) == want_internal && k-- == 0) return i;
  return t.root();
}

}  // namespace

Tree splice(const Tree& a, std::size_t i, const Tree& b, std::size_t j) {
  const std::size_t a0 = a.begin_of(i), b0 = b.begin_of(j);
  Tree c;
  c.nodes.reserve(a.size() - a.nodes[i].length + b.nodes[j].length);
  c.nodes.insert(c.nodes.end(), a.nodes.begin(), a.nodes.begin() + static_cast<std::ptrdiff_t>(a0));
  c.nodes.insert(c.nodes.end(), b.nodes.begin() + static_cast<std::ptrdiff_t>(b0),
                 b.nodes.begin() + static_cast<std::ptrdiff_t>(j + 1));
  c.nodes.insert(c.nodes.end(), a.nodes.begin() + static_cast<std::ptrdiff_t>(i + 1), a.nodes.end());
  // Ancestors of the splice point (nodes after it whose subtree in `a` covers node i)
  // change length by the difference.
  const std::size_t end = a0 + b.nodes[j].length;  // one past the inserted subtree in c
  for (std::size_t k = end; k < c.size(); ++k) {
    const std::size_t ak = k + a.nodes[i].length - b.nodes[j].length;  // index in a
    if (a.begin_of(ak) <= a0)
      c.nodes[k].length = static_cast<std::uint32_t>(a.nodes[ak].length + b.nodes[j].length -
                                                     a.nodes[i].length);
  }
  return c;
}

std::optional<std::pair<std::size_t, std::size_t>> crossover_points(
    const Tree& a, const Tree& b, const PrimitiveSet& /*set*/, Limits limits, double internal_bias,
    Rng& rng) {
  const std::vector<int> level = levels(a);
  const std::vector<int> bdepth = subtree_depths(b);
  std::vector<std::size_t> legal;
  legal.reserve(b.size());
  for (int attempt = 0; attempt < 8; ++attempt) {
    const std::size_t i = pick_point(a, internal_bias, rng);
    const Type t = a.nodes[i].type;
    const std::size_t rest = a.size() - a.nodes[i].length;
    legal.clear();
    for (std::size_t j = 0; j < b.size(); ++j) {
      if (b.nodes[j].type != t) continue;
      if (static_cast<int>(rest + b.nodes[j].length) > limits.max_size) continue;
      if (level[i] - 1 + bdepth[j] > limits.max_depth) continue;
      legal.push_back(j);
    }
    if (!legal.empty()) return std::make_pair(i, legal[rng.below(legal.size())]);
  }
  return std::nullopt;
}

Tree crossover(const Tree& a, const Tree& b, const PrimitiveSet& set, Limits limits,
               double internal_bias, Rng& rng) {
  const auto p = crossover_points(a, b, set, limits, internal_bias, rng);
  if (!p) return a;
  return splice(a, p->first, b, p->second);
}

Tree subtree_mutation(const Tree& a, const PrimitiveSet& set, Limits limits, int new_depth,
                      Rng& rng) {
  const std::vector<int> level = levels(a);
  for (int attempt = 0; attempt < 8; ++attempt) {
    const std::size_t i = rng.below(a.size());
    const Type t = a.nodes[i].type;
    const int room_depth = limits.max_depth - level[i] + 1;
    const int room_size = limits.max_size - static_cast<int>(a.size() - a.nodes[i].length);
    if (room_depth < set.min_depth(t) || room_size < set.min_size(t)) continue;
    const int d = std::min(new_depth, room_depth);
    Tree sub;
    for (int k = 0; k < 8; ++k) {
      sub.nodes.clear();
      append_random(set, t, d, false, rng, sub.nodes);
      if (static_cast<int>(sub.size()) <= room_size) break;
    }
    if (static_cast<int>(sub.size()) > room_size) sub = smallest(set, t, rng);
    return splice(a, i, sub, sub.root());
  }
  return a;
}

Tree point_mutation(const Tree& a, const PrimitiveSet& set, double erc_sigma, Rng& rng) {
  Tree c = a;
  const std::size_t i = rng.below(a.size());
  Node& n = c.nodes[i];
  const Primitive& p = set[n.prim];
  if (p.kind == Kind::Erc) {
    n.value += rng.normal() * erc_sigma * (p.hi - p.lo);
    if (!std::isfinite(n.value)) n.value = draw_erc(p, rng);
    return c;
  }
  std::vector<PrimitiveId> alternatives;
  for (PrimitiveId id : set.of_type(n.type))
    if (id != n.prim && set.same_signature(id, n.prim)) alternatives.push_back(id);
  if (alternatives.empty()) return c;
  const PrimitiveId id = alternatives[rng.below(alternatives.size())];
  const Primitive& q = set[id];
  const std::uint32_t len = n.length;
  n = make_node(set, id, q.kind == Kind::Erc ? draw_erc(q, rng) : 0.0);
  n.length = len;
  return c;
}

Tree hoist_mutation(const Tree& a, const PrimitiveSet& /*set*/, Rng& rng) {
  // Nodes with at least one proper descendant of their own type.
  std::vector<std::size_t> candidates;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Type t = a.nodes[i].type;
    for (std::size_t j = a.begin_of(i); j < i; ++j)
      if (a.nodes[j].type == t) {
        candidates.push_back(i);
        break;
      }
  }
  if (candidates.empty()) return a;
  const std::size_t i = candidates[rng.below(candidates.size())];
  std::vector<std::size_t> inner;
  for (std::size_t j = a.begin_of(i); j < i; ++j)
    if (a.nodes[j].type == a.nodes[i].type) inner.push_back(j);
  const std::size_t j = inner[rng.below(inner.size())];
  return splice(a, i, a, j);
}

}  // namespace esc::genome::tree
