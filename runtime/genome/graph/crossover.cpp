#include "runtime/genome/graph/crossover.hpp"

#include <algorithm>

namespace esc::genome::graph {

namespace {

void take_node(Graph& child, const Graph& owner, Id id) {
  if (node_index(child, id) == child.nodes.size()) insert_node(child, owner.nodes[node_index(owner, id)]);
}

}  // namespace

Graph mate(const Graph& mom, const Graph& dad, double mom_fitness, double dad_fitness, Mating how, Rng& rng) {
  const bool mom_better =
      mom_fitness > dad_fitness || (mom_fitness == dad_fitness && mom.links.size() < dad.links.size());
  Graph child;
  for (const NodeGene& n : dad.nodes)
    if (n.kind != NodeKind::Hidden) child.nodes.push_back(n);
  std::size_t i = 0, j = 0;
  const std::size_t n1 = mom.links.size(), n2 = dad.links.size();
  while (i < n1 || j < n2) {
    LinkGene chosen;
    const Graph* owner = &mom;
    bool skip = false;
    bool disable = false;
    if (i == n1) {
      chosen = dad.links[j++];
      owner = &dad;
      skip = mom_better;
    } else if (j == n2) {
      chosen = mom.links[i++];
      skip = !mom_better;
    } else if (mom.links[i].innovation == dad.links[j].innovation) {
      const LinkGene& a = mom.links[i++];
      const LinkGene& b = dad.links[j++];
      if (how == Mating::MultipointAverage) {
        chosen = a;
        chosen.weight = (a.weight + b.weight) / 2.0;
        chosen.enabled = true;
      } else if (rng.uniform() < 0.5) {
        chosen = a;
      } else {
        chosen = b;
        owner = &dad;
      }
      disable = (!a.enabled || !b.enabled) && rng.uniform() < kKeepDisabled;
    } else if (mom.links[i].innovation < dad.links[j].innovation) {
      chosen = mom.links[i++];
      skip = !mom_better;
    } else {
      chosen = dad.links[j++];
      owner = &dad;
      skip = mom_better;
    }
    if (skip) continue;
    const bool repeated = std::any_of(child.links.begin(), child.links.end(),
                                      [&](const LinkGene& l) { return l.in == chosen.in && l.out == chosen.out; });
    if (repeated) continue;
    take_node(child, *owner, chosen.in);
    take_node(child, *owner, chosen.out);
    if (disable) chosen.enabled = false;
    child.links.push_back(chosen);
  }
  return child;
}

}  // namespace esc::genome::graph
