#include "runtime/genome/graph/graph_operators.hpp"

#include "runtime/genome/graph/mutation.hpp"

namespace esc::genome::graph {

Graph start_graph(const GraphOperators& ops, std::size_t inputs, std::size_t outputs, Activation output_activation) {
  Graph g = hidden_layer_graph(inputs, outputs, static_cast<std::size_t>(ops.start_hidden), ops.activation);
  for (NodeGene& n : g.nodes)
    if (n.kind == NodeKind::Output) n.activation = output_activation;
  return g;
}

void mutate(Graph& g, const GraphOperators& ops, InnovationRecord& record, Rng& rng) {
  if (rng.uniform() < ops.add_node_prob) {
    (void)add_node(g, record, ops.activation, rng);
  } else if (rng.uniform() < ops.add_link_prob) {
    (void)add_link(g, record, ops.recur_only_prob, ops.newlink_tries, ops.new_link_weight, rng);
  } else {
    if (rng.uniform() < ops.weight_mut_prob) mutate_weights(g, ops.weight_mut_power, rng);
    if (rng.uniform() < ops.toggle_enable_prob) toggle_enable(g, rng);
    if (rng.uniform() < ops.reenable_prob) reenable(g);
  }
}

}  // namespace esc::genome::graph
