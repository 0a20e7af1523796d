// A `neat(...)` controller: its graph genome built into NEAT's network, activated once per
// step with the head's activation on the output nodes, reset at each epoch, rebound to
// another graph, and refusing a genome that is not a graph of its inputs and outputs.
#include <cmath>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "runtime/control/controller.hpp"
#include "runtime/control/graph_net.hpp"
#include "runtime/genome/graph/codec.hpp"
#include "runtime/genome/graph/graph.hpp"

namespace esc::control {
namespace {

namespace gg = genome::graph;

ControllerSpec neat_classical() {
  ControllerSpec s;
  s.name = "tiny_neat";
  s.mlp.inputs = {expr::slot::ir, expr::slot::ir + 1};
  s.mlp.kind = NetworkKind::Graph;
  return s;
}

// The minimal 2-input, 2-output graph (links: per output, input 1, input 2, bias), weights
// given, output nodes in the head's activation.
std::vector<double> minimal(const std::vector<double>& weights, gg::Activation output) {
  gg::Graph g = gg::minimal_graph(2, 2, gg::Activation::NeatSigmoid);
  for (gg::NodeGene& n : g.nodes)
    if (n.kind == gg::NodeKind::Output) n.activation = output;
  for (std::size_t i = 0; i < g.links.size(); ++i) g.links[i].weight = weights[i];
  return gg::encode(g);
}

TEST(GraphController, AClassicalNeatNetworkDrivesTheWheelsWithTanhOutputs) {
  const ControllerSpec spec = neat_classical();
  EXPECT_TRUE(spec.is_graph());
  EXPECT_EQ(spec.genome_size(), 0u);
  EXPECT_EQ(spec.architecture(), "2-neat-2");
  EXPECT_EQ(graph_activation(output_activation(spec.head)), gg::Activation::Tanh);
  const std::vector<double> genome = minimal({0.5, -0.3, 0.1, 1.0, 0.2, -0.4}, gg::Activation::Tanh);
  Controller c(spec, genome);
  expr::Frame f{};
  f[expr::slot::ir] = 0.6;
  f[expr::slot::ir + 1] = 0.2;
  const WheelCommand w = c.step(f);
  EXPECT_DOUBLE_EQ(w.left, std::tanh(0.5 * 0.6 - 0.3 * 0.2 + 0.1));
  EXPECT_DOUBLE_EQ(w.right, std::tanh(1.0 * 0.6 + 0.2 * 0.2 - 0.4));
  // Another network, rebound: its own outputs.
  c.rebind(minimal({0.0, 0.0, 0.0, 0.0, 0.0, 2.0}, gg::Activation::Tanh));
  const WheelCommand v = c.step(f);
  EXPECT_DOUBLE_EQ(v.left, 0.0);
  EXPECT_DOUBLE_EQ(v.right, std::tanh(2.0));
}

TEST(GraphController, AHiddenNodeAnswersOneStepLateAndResetClearsIt) {
  // input 1 -> hidden -> output 1 (linear everywhere): the output reads the hidden node's
  // previous value, so a network of depth 2 answers one step late; reset() forgets.
  gg::Graph g = gg::minimal_graph(2, 2, gg::Activation::Linear);
  for (gg::LinkGene& l : g.links) l.weight = 0.0;
  const gg::Id out = g.nodes[3].id;
  gg::insert_node(g, {10, gg::NodeKind::Hidden, gg::Activation::Linear});
  gg::insert_link(g, {1, 10, 1.0, true, 100});
  gg::insert_link(g, {10, out, 1.0, true, 101});
  const std::vector<double> genome = gg::encode(g);
  const ControllerSpec spec = neat_classical();
  Controller c(spec, genome);
  expr::Frame f{};
  f[expr::slot::ir] = 0.7;
  const double first = c.step(f).left;
  const double second = c.step(f).left;
  EXPECT_DOUBLE_EQ(second, 0.7);
  EXPECT_NE(first, second);
  c.reset();
  EXPECT_DOUBLE_EQ(c.step(f).left, first);
}

TEST(GraphController, AGenomeThatIsNotAGraphOfItsShapeIsRefused) {
  const ControllerSpec spec = neat_classical();
  EXPECT_THROW(Controller(spec, std::vector<double>(6, 0.1)), std::invalid_argument);
  gg::Graph wide = gg::minimal_graph(3, 2, gg::Activation::Tanh);
  const std::vector<double> three = gg::encode(wide);
  EXPECT_THROW(Controller(spec, three), std::invalid_argument);
  EXPECT_NE(graph_genome_problem(spec, three).find("3 inputs"), std::string::npos) << graph_genome_problem(spec, three);
  EXPECT_EQ(graph_genome_problem(spec, minimal({1, 1, 1, 1, 1, 1}, gg::Activation::Tanh)), "");
}

}  // namespace
}  // namespace esc::control
