#pragma once
// The two parents of the NEAT paper's Figure 4 (Stanley & Miikkulainen 2002): inputs 1-3
// (3 standing in for the bias here), output 4, hidden 5 and 6; parent 1 has innovations
// 1-5 and 8, parent 2 innovations 1-7, 9 and 10; weights chosen so each link is told apart.
#include "runtime/genome/graph/graph.hpp"

namespace esc::genome::graph::testing {

inline Graph figure4_parent1() {
  Graph g;
  g.nodes = {
      {1, NodeKind::Input}, {2, NodeKind::Input}, {3, NodeKind::Bias}, {4, NodeKind::Output}, {5, NodeKind::Hidden}};
  g.links = {{1, 4, 0.1, true, 1}, {2, 4, 0.2, false, 2}, {3, 4, 0.3, true, 3},
             {2, 5, 0.4, true, 4}, {5, 4, 0.5, true, 5}, {1, 5, 0.8, true, 8}};
  return g;
}

inline Graph figure4_parent2() {
  Graph g;
  g.nodes = {{1, NodeKind::Input},  {2, NodeKind::Input},  {3, NodeKind::Bias},
             {4, NodeKind::Output}, {5, NodeKind::Hidden}, {6, NodeKind::Hidden}};
  g.links = {{1, 4, -0.1, true, 1}, {2, 4, -0.2, false, 2}, {3, 4, -0.3, true, 3}, {2, 5, -0.4, true, 4},
             {5, 4, -0.5, false, 5}, {5, 6, -0.6, true, 6}, {6, 4, -0.7, true, 7}, {3, 5, -0.9, true, 9},
             {1, 6, -1.0, true, 10}};
  return g;
}

}  // namespace esc::genome::graph::testing
