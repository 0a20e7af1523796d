#pragma once
// A graph genome as text a person reads: its nodes, then one line per link, in innovation
// order, disabled links marked. For logs, test failures and `esc show`-style output.
#include <string>

#include "runtime/genome/graph/graph.hpp"

namespace esc::genome::graph {

// "nodes: 1 input, 2 input, 3 bias, 4 output neat_sigmoid, 5 hidden neat_sigmoid\n"
// "link 1: 1 -> 4 weight 0.5\n" ... "link 6: 3 -> 5 weight -1.25 disabled\n"
[[nodiscard]] std::string print(const Graph& g);

}  // namespace esc::genome::graph
