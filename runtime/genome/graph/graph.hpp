#pragma once
// NEAT's genome (Stanley & Miikkulainen 2002, section 3.1): node genes and connection
// ("link") genes, each link carrying the innovation number of the structural mutation that
// first made it, so that two genomes line up gene by gene without analysing their topology.
// Nodes are kept sorted by id, links by innovation; the input and bias nodes (the sensors)
// come first, as NEAT C++ keeps them, so that the mutations that pick "a node that is not a
// sensor" pick by position.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace esc::genome::graph {

using Id = std::int64_t;

enum class NodeKind : std::uint8_t { Input, Bias, Hidden, Output };

// NeatSigmoid is NEAT C++'s steepened logistic 1 / (1 + exp(-4.924273 x)) (network.cpp's
// fsigmoid with slope 4.924273); the other three are the script language's activations.
enum class Activation : std::uint8_t { NeatSigmoid, Tanh, Sigmoid, Linear };

struct NodeGene {
  Id id = 0;
  NodeKind kind = NodeKind::Hidden;
  Activation activation = Activation::NeatSigmoid;   // unused by sensors
  friend bool operator==(const NodeGene&, const NodeGene&) = default;
};

struct LinkGene {
  Id in = 0;
  Id out = 0;
  double weight = 0.0;
  bool enabled = true;
  Id innovation = 0;
  friend bool operator==(const LinkGene&, const LinkGene&) = default;
};

struct Graph {
  std::vector<NodeGene> nodes;   // by id, sensors first
  std::vector<LinkGene> links;   // by innovation
  friend bool operator==(const Graph&, const Graph&) = default;
};

[[nodiscard]] std::string_view kind_name(NodeKind kind);
[[nodiscard]] std::string_view activation_name(Activation activation);

// NEAT's minimal start: `inputs` input nodes (ids 1..inputs), the bias (inputs + 1), then
// `outputs` output nodes, and a link from every sensor to every output, weight 0, numbered
// 1, 2, ... output by output (the optimizer draws the weights).
[[nodiscard]] Graph minimal_graph(std::size_t inputs, std::size_t outputs, Activation activation);

// The same sensors and outputs with `hidden` hidden nodes between them (ids after the
// outputs'): a link from every sensor to each hidden node, then from each hidden node to
// every output, weight 0, numbered in that order; no sensor-to-output link. `hidden` 0 is
// minimal_graph.
[[nodiscard]] Graph hidden_layer_graph(std::size_t inputs, std::size_t outputs, std::size_t hidden,
                                       Activation activation);

// What is wrong with `g`, in one sentence, or "": nodes out of order or repeated, a sensor
// after another node, not exactly one bias, no output, a link at an unknown node, into a
// sensor, repeated (same innovation, or same two nodes), out of order, or with a weight
// that is not finite.
[[nodiscard]] std::string misfit(const Graph& g);

// Position of node `id` in g.nodes, or g.nodes.size() when absent.
[[nodiscard]] std::size_t node_index(const Graph& g, Id id);
[[nodiscard]] std::size_t count_nodes(const Graph& g, NodeKind kind);
[[nodiscard]] std::size_t sensor_count(const Graph& g);
[[nodiscard]] std::size_t enabled_links(const Graph& g);
// One past the largest node id / innovation in g (1 for none): where new ones start.
[[nodiscard]] Id next_node_id(const Graph& g);
[[nodiscard]] Id next_innovation(const Graph& g);

// Inserts `link` in innovation order, `node` in id order.
void insert_link(Graph& g, const LinkGene& link);
void insert_node(Graph& g, const NodeGene& node);

}  // namespace esc::genome::graph
