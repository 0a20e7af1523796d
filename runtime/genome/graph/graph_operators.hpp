#pragma once
// NEAT's variation settings, as every algorithm that varies graph genomes takes them: NEAT's
// own reproduction, and NSGA-II, novelty search and MAP-Elites over `neat(...)` controllers
// (graph_variation.hpp). The values come from NEAT's settings (evo/neat/neat_settings.hpp,
// where their defaults and sources live; graph_operators() there); here they have none.
// Also what a start genome is, and NEAT C++'s order of one genome's mutations.
#include "runtime/core/rng.hpp"
#include "runtime/genome/graph/graph.hpp"
#include "runtime/genome/graph/innovation.hpp"

namespace esc::genome::graph {

struct GraphOperators {
  double mutate_only_prob = 0.0;      // a child by mutation alone, without crossover
  double mate_only_prob = 0.0;        // a child of crossover left unmutated
  double mate_multipoint_prob = 0.0;  // a crossover takes each matching link from one parent
  double weight_mut_prob = 0.0;
  double weight_mut_power = 0.0;
  double toggle_enable_prob = 0.0;
  double reenable_prob = 0.0;
  double add_node_prob = 0.0;
  double add_link_prob = 0.0;
  double recur_only_prob = 0.0;
  int newlink_tries = 0;
  double new_link_weight = 0.0;
  Activation activation = Activation::NeatSigmoid;   // of hidden nodes
  int start_hidden = 0;
  friend bool operator==(const GraphOperators&, const GraphOperators&) = default;
};

// The range of a start genome's weights, drawn anew per copy (NEAT C++'s Population::spawn:
// mutate_link_weights(1.0, 1.0, COLDGAUSSIAN)).
inline constexpr double kStartWeight = 1.0;

// The genome every first population copies: `inputs` sensors and a bias, `outputs` outputs
// of activation `output_activation`, and start_hidden hidden nodes between (hidden_layer_graph).
[[nodiscard]] Graph start_graph(const GraphOperators& ops, std::size_t inputs, std::size_t outputs,
                                Activation output_activation);

// One genome's mutation, in NEAT C++'s order (Species::reproduce): add-node with its
// probability; else add-link with its own; else the weights (weight_mut_prob), a toggle
// (toggle_enable_prob) and a re-enabling (reenable_prob), each drawn in turn.
void mutate(Graph& g, const GraphOperators& ops, InnovationRecord& record, Rng& rng);

}  // namespace esc::genome::graph
