#pragma once
// What a problem that evolves graph genomes (NEAT's) says about them: the network's inputs
// and outputs (a bias is added) and the activation its output nodes take, the one the
// controller's head wants from a network's outputs (tanh for wheel commands, the logistic
// for choices); hidden nodes take the algorithm's own. Header only: the optimizers'
// interface holds it without linking the graph genome.
#include <cstddef>

#include "runtime/genome/graph/graph.hpp"
#include "runtime/genome/graph/graph_operators.hpp"

namespace esc::genome::graph {

struct GraphSpace {
  std::size_t inputs = 0;
  std::size_t outputs = 0;   // 0: the problem evolves no graphs
  Activation output_activation = Activation::NeatSigmoid;
  // How an algorithm other than NEAT varies them: NEAT's settings in the experiment
  // (`evolve neat(...)`, else its defaults).
  GraphOperators operators = {};
  [[nodiscard]] bool graphs() const noexcept { return outputs > 0; }
  friend bool operator==(const GraphSpace&, const GraphSpace&) = default;
};

}  // namespace esc::genome::graph
