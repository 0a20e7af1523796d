// The graph genome's form: NEAT's minimal start, the checks misfit() makes, the flat encoding
// and its round trip, the text form.
#include <gtest/gtest.h>

#include "runtime/genome/graph/codec.hpp"
#include "runtime/genome/graph/graph.hpp"
#include "runtime/genome/graph/print.hpp"
#include "tests/genome_graph/figure4.hpp"

namespace esc::genome::graph {
namespace {

TEST(GraphGenome, MinimalStartWiresEverySensorToEveryOutput) {
  const Graph g = minimal_graph(2, 2, Activation::NeatSigmoid);
  ASSERT_EQ(g.nodes.size(), 5U);
  EXPECT_EQ(g.nodes[2].kind, NodeKind::Bias);
  EXPECT_EQ(g.nodes[3].kind, NodeKind::Output);
  ASSERT_EQ(g.links.size(), 6U);
  EXPECT_EQ(g.links[0], (LinkGene{1, 4, 0.0, true, 1}));
  EXPECT_EQ(g.links[5], (LinkGene{3, 5, 0.0, true, 6}));
  EXPECT_EQ(misfit(g), "");
  EXPECT_EQ(next_node_id(g), 6);
  EXPECT_EQ(next_innovation(g), 7);
}

TEST(GraphGenome, MisfitNamesWhatIsWrong) {
  Graph g = testing::figure4_parent1();
  EXPECT_EQ(misfit(g), "");
  Graph dup = g;
  dup.links[5].innovation = 5;
  EXPECT_EQ(misfit(dup), "innovation 5 appears twice");
  Graph dangling = g;
  dangling.links[5].in = 9;
  EXPECT_EQ(misfit(dangling), "link 8 (9 -> 5) reaches unknown node 9");
  Graph into_sensor = g;
  into_sensor.links[5].out = 2;
  EXPECT_EQ(misfit(into_sensor), "link 8 ends at input node 2: sensors take no links");
  Graph twice = g;
  twice.links[5].in = 2;
  EXPECT_EQ(misfit(twice), "link 8 joins 2 -> 5 again");
  Graph no_bias = g;
  no_bias.nodes[2].kind = NodeKind::Input;
  EXPECT_EQ(misfit(no_bias), "the genome has 0 bias nodes, not 1");
  Graph unordered = g;
  std::swap(unordered.links[0], unordered.links[1]);
  EXPECT_EQ(misfit(unordered), "link 1 comes after link 2: links must be in innovation order");
  Graph late_sensor = g;
  late_sensor.nodes[4].kind = NodeKind::Input;
  EXPECT_EQ(misfit(late_sensor), "input node 5 comes after a hidden or output node");
}

TEST(GraphGenome, EncodingRoundTripsExactly) {
  Graph g = testing::figure4_parent2();
  g.links[3].weight = 0.1 + 0.2;   // not a short decimal
  g.nodes[5].activation = Activation::Tanh;
  const std::vector<double> genes = encode(g);
  EXPECT_EQ(genes.size(), encoded_size(6, 9));
  Graph back;
  ASSERT_EQ(decode(genes, back), "");
  EXPECT_EQ(back, g);
}

TEST(GraphGenome, DecodeRefusesWhatIsNotAGraph) {
  const std::vector<double> genes = encode(testing::figure4_parent1());
  Graph out;
  std::vector<double> v = genes;
  v[0] = 2.0;
  EXPECT_EQ(decode(v, out), "graph genome version 2, expected 1");
  v = genes;
  v.pop_back();
  EXPECT_EQ(decode(v, out), "5 nodes and 6 links take 48 numbers, found 47");
  v = genes;
  v[3 + 3 * 5 + 5 * 5 + 4] = 1.0;   // the last link's innovation becomes 1, repeated
  EXPECT_EQ(decode(v, out), "link 1 comes after link 5: links must be in innovation order");
  v = genes;
  v[3 + 1] = 7.0;
  EXPECT_EQ(decode(v, out), "node 1: kind 7 is none of input, bias, hidden, output");
  v = genes;
  v[3 + 3 * 5 + 3] = 0.5;
  EXPECT_EQ(decode(v, out), "link 1: enabled is 0.5, neither 0 nor 1");
  EXPECT_EQ(decode(std::vector<double>{1.0}, out), "a graph genome has at least 3 numbers, found 1");
  EXPECT_TRUE(out.nodes.empty());   // untouched by every refusal
}

TEST(GraphGenome, PrintsOneLinePerLink) {
  const std::string text = print(testing::figure4_parent1());
  EXPECT_EQ(text.substr(0, text.find('\n')),
            "nodes: 1 input, 2 input, 3 bias, 4 output neat_sigmoid, 5 hidden neat_sigmoid");
  EXPECT_NE(text.find("link 2: 2 -> 4 weight 0.2 disabled\n"), std::string::npos);
  EXPECT_NE(text.find("link 8: 1 -> 5 weight 0.8\n"), std::string::npos);
}

}  // namespace
}  // namespace esc::genome::graph
