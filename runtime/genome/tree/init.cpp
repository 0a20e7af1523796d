#include "runtime/genome/tree/init.hpp"

#include <algorithm>
#include <array>

namespace esc::genome::tree {

namespace {

// Picks uniformly among the primitives of `type` that finish within `remaining` levels;
// with `full`, among those that are not terminals if any such fits.
PrimitiveId pick(const PrimitiveSet& set, Type type, int remaining, bool want_function, Rng& rng) {
  std::array<PrimitiveId, 256> buf{};
  std::vector<PrimitiveId> big;
  std::size_t n = 0;
  const auto ids = set.of_type(type);
  const auto collect = [&](bool functions_only) {
    n = 0;
    big.clear();
    for (PrimitiveId id : ids) {
      if (set.min_depth_of(id) > remaining) continue;
      if (functions_only && set[id].terminal()) continue;
      if (n < buf.size()) buf[n] = id;
      else big.push_back(id);
      ++n;
    }
  };
  collect(want_function && remaining > 1);
  if (n == 0) collect(false);
  if (n == 0) {  // remaining below the type's minimum depth: take the shallowest primitive
    PrimitiveId best = ids.front();
    for (PrimitiveId id : ids)
      if (set.min_depth_of(id) < set.min_depth_of(best)) best = id;
    return best;
  }
  const std::size_t k = rng.below(n);
  return k < buf.size() ? buf[k] : big[k - buf.size()];
}

void build(const PrimitiveSet& set, Type type, int remaining, bool full, Rng& rng,
           std::vector<Node>& out) {
  const PrimitiveId id = pick(set, type, remaining, full, rng);
  const Primitive& p = set[id];
  const std::size_t first = out.size();
  for (Type a : p.arg_types()) build(set, a, remaining - 1, full, rng, out);
  Node n = make_node(set, id, p.kind == Kind::Erc ? draw_erc(p, rng) : 0.0);
  n.length = static_cast<std::uint32_t>(out.size() - first + 1);
  out.push_back(n);
}

void build_smallest(const PrimitiveSet& set, Type type, Rng& rng, std::vector<Node>& out) {
  const auto ids = set.of_type(type);
  PrimitiveId best = ids.front();
  for (PrimitiveId id : ids)
    if (set.min_size_of(id) < set.min_size_of(best)) best = id;
  const Primitive& p = set[best];
  const std::size_t first = out.size();
  for (Type a : p.arg_types()) build_smallest(set, a, rng, out);
  Node n = make_node(set, best, p.kind == Kind::Erc ? draw_erc(p, rng) : 0.0);
  n.length = static_cast<std::uint32_t>(out.size() - first + 1);
  out.push_back(n);
}

}  // namespace

double draw_erc(const Primitive& p, Rng& rng) noexcept { return rng.uniform(p.lo, p.hi); }

void append_random(const PrimitiveSet& set, Type type, int max_depth, bool full, Rng& rng,
                   std::vector<Node>& out) {
  build(set, type, std::max(max_depth, set.min_depth(type)), full, rng, out);
}

Tree grow(const PrimitiveSet& set, Type type, int max_depth, Rng& rng) {
  Tree t;
  append_random(set, type, max_depth, false, rng, t.nodes);
  return t;
}

Tree full(const PrimitiveSet& set, Type type, int depth, Rng& rng) {
  Tree t;
  append_random(set, type, depth, true, rng, t.nodes);
  return t;
}

Tree smallest(const PrimitiveSet& set, Type type, Rng& rng) {
  Tree t;
  build_smallest(set, type, rng, t.nodes);
  return t;
}

std::vector<Tree> ramped_half_and_half(const PrimitiveSet& set, std::size_t count, int min_depth,
                                       int max_depth, int max_size, Rng& rng) {
  const Type root = set.root();
  min_depth = std::max(min_depth, set.min_depth(root));
  max_depth = std::max(max_depth, min_depth);
  const auto range = static_cast<std::size_t>(max_depth - min_depth + 1);
  std::vector<Tree> out;
  out.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    const int d = min_depth + static_cast<int>(i % range);
    const bool is_full = (i / range) % 2 == 0;
    Tree t;
    bool ok = false;
    for (int dd = d; dd >= set.min_depth(root) && !ok; --dd)
      for (int attempt = 0; attempt < 20 && !ok; ++attempt) {
        t = is_full ? full(set, root, dd, rng) : grow(set, root, dd, rng);
        ok = static_cast<int>(t.size()) <= max_size;
      }
    if (!ok) t = smallest(set, root, rng);
    out.push_back(std::move(t));
  }
  return out;
}

}  // namespace esc::genome::tree
