#include "runtime/genome/graph/print.hpp"

#include <fmt/format.h>

namespace esc::genome::graph {

std::string print(const Graph& g) {
  std::string s = "nodes:";
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    const NodeGene& n = g.nodes[i];
    s += fmt::format("{} {} {}", i == 0 ? "" : ",", n.id, kind_name(n.kind));
    if (n.kind == NodeKind::Hidden || n.kind == NodeKind::Output)
      s += fmt::format(" {}", activation_name(n.activation));
  }
  s += '\n';
  for (const LinkGene& l : g.links)
    s += fmt::format("link {}: {} -> {} weight {}{}\n", l.innovation, l.in, l.out, l.weight,
                     l.enabled ? "" : " disabled");
  return s;
}

}  // namespace esc::genome::graph
