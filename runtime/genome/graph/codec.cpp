#include "runtime/genome/graph/codec.hpp"

#include <cmath>

#include <fmt/format.h>

namespace esc::genome::graph {

namespace {

constexpr std::size_t kHeader = 3;
constexpr double kMaxExact = 9007199254740992.0;   // 2^53

bool whole(double v, double lo, double hi) { return v == std::floor(v) && v >= lo && v <= hi; }

}  // namespace

std::size_t encoded_size(std::size_t nodes, std::size_t links) {
  return kHeader + kCodedNodeWidth * nodes + kCodedLinkWidth * links;
}

std::vector<double> encode(const Graph& g) {
  std::vector<double> out;
  out.reserve(encoded_size(g.nodes.size(), g.links.size()));
  out.push_back(kCodecVersion);
  out.push_back(static_cast<double>(g.nodes.size()));
  out.push_back(static_cast<double>(g.links.size()));
  for (const NodeGene& n : g.nodes) {
    out.push_back(static_cast<double>(n.id));
    out.push_back(static_cast<double>(n.kind));
    out.push_back(static_cast<double>(n.activation));
  }
  for (const LinkGene& l : g.links) {
    out.push_back(static_cast<double>(l.in));
    out.push_back(static_cast<double>(l.out));
    out.push_back(l.weight);
    out.push_back(l.enabled ? 1.0 : 0.0);
    out.push_back(static_cast<double>(l.innovation));
  }
  return out;
}

std::string decode(std::span<const double> genes, Graph& out) {
  if (genes.size() < kHeader)
    return fmt::format("a graph genome has at least {} numbers, found {}", kHeader, genes.size());
  if (genes[0] != kCodecVersion) return fmt::format("graph genome version {}, expected {}", genes[0], kCodecVersion);
  if (!whole(genes[1], 0, kMaxExact) || !whole(genes[2], 0, kMaxExact))
    return "the node or link count is not a whole number";
  const auto nodes = static_cast<std::size_t>(genes[1]);
  const auto links = static_cast<std::size_t>(genes[2]);
  if (nodes > genes.size() || links > genes.size() || genes.size() != encoded_size(nodes, links))
    return fmt::format("{} nodes and {} links take {} numbers, found {}", genes[1], genes[2],
                       nodes > genes.size() || links > genes.size() ? 0 : encoded_size(nodes, links), genes.size());
  Graph g;
  g.nodes.reserve(nodes);
  g.links.reserve(links);
  std::size_t at = kHeader;
  for (std::size_t i = 0; i < nodes; ++i, at += kCodedNodeWidth) {
    const double id = genes[at], kind = genes[at + 1], act = genes[at + 2];
    if (!whole(id, 1, kMaxExact))
      return fmt::format("node {} of {}: its id {} is not a whole number from 1", i + 1, nodes, id);
    if (!whole(kind, 0, static_cast<double>(NodeKind::Output)))
      return fmt::format("node {}: kind {} is none of input, bias, hidden, output", id, kind);
    if (!whole(act, 0, static_cast<double>(Activation::Linear)))
      return fmt::format("node {}: activation {} is none of neat_sigmoid, tanh, sigmoid, linear", id, act);
    g.nodes.push_back({static_cast<Id>(id), static_cast<NodeKind>(kind), static_cast<Activation>(act)});
  }
  for (std::size_t i = 0; i < links; ++i, at += kCodedLinkWidth) {
    const double in = genes[at], o = genes[at + 1], enabled = genes[at + 3], innovation = genes[at + 4];
    if (!whole(innovation, 1, kMaxExact))
      return fmt::format("link {} of {}: its innovation {} is not a whole number from 1", i + 1, links, innovation);
    if (!whole(in, 1, kMaxExact) || !whole(o, 1, kMaxExact))
      return fmt::format("link {}: a node id is not a whole number from 1", innovation);
    if (enabled != 0.0 && enabled != 1.0)
      return fmt::format("link {}: enabled is {}, neither 0 nor 1", innovation, enabled);
    g.links.push_back(
        {static_cast<Id>(in), static_cast<Id>(o), genes[at + 2], enabled == 1.0, static_cast<Id>(innovation)});
  }
  if (std::string why = misfit(g); !why.empty()) return why;
  out = std::move(g);
  return {};
}

}  // namespace esc::genome::graph
