#include "runtime/genome/tree/codec.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace esc::genome::tree {

void encode(const Tree& tree, std::vector<double>& out) {
  out.reserve(out.size() + kCodedNodeWidth * tree.size());
  for (const Node& n : tree.nodes) {
    out.push_back(static_cast<double>(n.prim));
    out.push_back(n.value);
  }
}

std::vector<double> encode(const Tree& tree) {
  std::vector<double> out;
  encode(tree, out);
  return out;
}

Tree decode(std::span<const double> genes, const PrimitiveSet& set) {
  const auto fail = [](const std::string& why) { throw std::invalid_argument("encoded tree: " + why); };
  if (genes.empty() || genes.size() % kCodedNodeWidth != 0)
    fail("expected a positive, even number of values, got " + std::to_string(genes.size()));
  Tree t;
  t.nodes.reserve(genes.size() / kCodedNodeWidth);
  for (std::size_t i = 0; i < genes.size(); i += kCodedNodeWidth) {
    const double id = genes[i];
    if (!(id >= 0.0 && id < static_cast<double>(set.size()) && std::floor(id) == id))
      fail("node " + std::to_string(i / kCodedNodeWidth) + " names no primitive of the set");
    t.nodes.push_back(make_node(set, static_cast<PrimitiveId>(id), genes[i + 1]));
  }
  if (!update_lengths(t)) fail("the arities do not form one tree");
  if (const std::string why = check(t, set, set.root()); !why.empty()) fail(why);
  return t;
}

}  // namespace esc::genome::tree
