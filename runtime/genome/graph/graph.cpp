#include "runtime/genome/graph/graph.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include <fmt/format.h>

namespace esc::genome::graph {

std::string_view kind_name(NodeKind kind) {
  switch (kind) {
    case NodeKind::Input: return "input";
    case NodeKind::Bias: return "bias";
    case NodeKind::Hidden: return "hidden";
    case NodeKind::Output: return "output";
  }
  return "?";
}

std::string_view activation_name(Activation activation) {
  switch (activation) {
    case Activation::NeatSigmoid: return "neat_sigmoid";
    case Activation::Tanh: return "tanh";
    case Activation::Sigmoid: return "sigmoid";
    case Activation::Linear: return "linear";
  }
  return "?";
}

Graph minimal_graph(std::size_t inputs, std::size_t outputs, Activation activation) {
  Graph g;
  Id id = 1;
  for (std::size_t i = 0; i < inputs; ++i) g.nodes.push_back({id++, NodeKind::Input, activation});
  g.nodes.push_back({id++, NodeKind::Bias, activation});
  Id innovation = 1;
  for (std::size_t o = 0; o < outputs; ++o) {
    const Id out = id++;
    g.nodes.push_back({out, NodeKind::Output, activation});
    for (Id s = 1; s <= static_cast<Id>(inputs) + 1; ++s) g.links.push_back({s, out, 0.0, true, innovation++});
  }
  return g;
}

Graph hidden_layer_graph(std::size_t inputs, std::size_t outputs, std::size_t hidden, Activation activation) {
  if (hidden == 0) return minimal_graph(inputs, outputs, activation);
  Graph g;
  Id id = 1;
  for (std::size_t i = 0; i < inputs; ++i) g.nodes.push_back({id++, NodeKind::Input, activation});
  g.nodes.push_back({id++, NodeKind::Bias, activation});
  const Id first_output = id;
  for (std::size_t o = 0; o < outputs; ++o) g.nodes.push_back({id++, NodeKind::Output, activation});
  const Id first_hidden = id;
  for (std::size_t h = 0; h < hidden; ++h) g.nodes.push_back({id++, NodeKind::Hidden, activation});
  Id innovation = 1;
  for (Id h = first_hidden; h < first_hidden + static_cast<Id>(hidden); ++h)
    for (Id s = 1; s < first_output; ++s) g.links.push_back({s, h, 0.0, true, innovation++});
  for (Id h = first_hidden; h < first_hidden + static_cast<Id>(hidden); ++h)
    for (Id o = first_output; o < first_hidden; ++o) g.links.push_back({h, o, 0.0, true, innovation++});
  return g;
}

namespace {

bool is_sensor(NodeKind k) { return k == NodeKind::Input || k == NodeKind::Bias; }

}  // namespace

std::string misfit(const Graph& g) {
  bool others = false;
  std::size_t biases = 0, outputs = 0;
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    const NodeGene& n = g.nodes[i];
    if (n.id <= 0) return fmt::format("node {} has an id below 1", n.id);
    if (i > 0 && n.id <= g.nodes[i - 1].id)
      return n.id == g.nodes[i - 1].id ? fmt::format("node {} appears twice", n.id)
                                       : fmt::format("node {} comes after node {}: nodes must be in id order", n.id,
                                                     g.nodes[i - 1].id);
    if (is_sensor(n.kind) && others)
      return fmt::format("{} node {} comes after a hidden or output node", kind_name(n.kind), n.id);
    others = others || !is_sensor(n.kind);
    biases += n.kind == NodeKind::Bias ? 1 : 0;
    outputs += n.kind == NodeKind::Output ? 1 : 0;
  }
  if (biases != 1) return fmt::format("the genome has {} bias nodes, not 1", biases);
  if (outputs == 0) return "the genome has no output node";
  std::set<std::pair<Id, Id>> pairs;
  for (std::size_t i = 0; i < g.links.size(); ++i) {
    const LinkGene& l = g.links[i];
    if (i > 0 && l.innovation <= g.links[i - 1].innovation)
      return l.innovation == g.links[i - 1].innovation
                 ? fmt::format("innovation {} appears twice", l.innovation)
                 : fmt::format("link {} comes after link {}: links must be in innovation order", l.innovation,
                               g.links[i - 1].innovation);
    if (l.innovation <= 0) return fmt::format("link {} has an innovation below 1", l.innovation);
    for (const Id end : {l.in, l.out})
      if (node_index(g, end) == g.nodes.size())
        return fmt::format("link {} ({} -> {}) reaches unknown node {}", l.innovation, l.in, l.out, end);
    if (const NodeKind k = g.nodes[node_index(g, l.out)].kind; is_sensor(k))
      return fmt::format("link {} ends at {} node {}: sensors take no links", l.innovation, kind_name(k), l.out);
    if (!pairs.insert({l.in, l.out}).second)
      return fmt::format("link {} joins {} -> {} again", l.innovation, l.in, l.out);
    if (!std::isfinite(l.weight)) return fmt::format("link {} has a weight that is not finite", l.innovation);
  }
  return {};
}

std::size_t node_index(const Graph& g, Id id) {
  const auto it =
      std::lower_bound(g.nodes.begin(), g.nodes.end(), id, [](const NodeGene& n, Id v) { return n.id < v; });
  return it != g.nodes.end() && it->id == id ? static_cast<std::size_t>(it - g.nodes.begin()) : g.nodes.size();
}

std::size_t count_nodes(const Graph& g, NodeKind kind) {
  return static_cast<std::size_t>(
      std::count_if(g.nodes.begin(), g.nodes.end(), [&](const NodeGene& n) { return n.kind == kind; }));
}

std::size_t sensor_count(const Graph& g) {
  return count_nodes(g, NodeKind::Input) + count_nodes(g, NodeKind::Bias);
}

std::size_t enabled_links(const Graph& g) {
  return static_cast<std::size_t>(
      std::count_if(g.links.begin(), g.links.end(), [](const LinkGene& l) { return l.enabled; }));
}

Id next_node_id(const Graph& g) { return g.nodes.empty() ? 1 : g.nodes.back().id + 1; }
Id next_innovation(const Graph& g) { return g.links.empty() ? 1 : g.links.back().innovation + 1; }

void insert_link(Graph& g, const LinkGene& link) {
  const auto at = std::upper_bound(g.links.begin(), g.links.end(), link.innovation,
                                   [](Id v, const LinkGene& l) { return v < l.innovation; });
  g.links.insert(at, link);
}

void insert_node(Graph& g, const NodeGene& node) {
  const auto at =
      std::upper_bound(g.nodes.begin(), g.nodes.end(), node.id, [](Id v, const NodeGene& n) { return v < n.id; });
  g.nodes.insert(at, node);
}

}  // namespace esc::genome::graph
