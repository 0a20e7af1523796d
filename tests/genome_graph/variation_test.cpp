// Graph genomes varied outside NEAT (graph_variation.hpp): the first genomes are NEAT's
// start, misfits are named, children are graph genomes of the same inputs and outputs whose
// new structure is numbered past the genomes bred from, the same in a generation, and the
// same draws give the same children.
#include <gtest/gtest.h>

#include <algorithm>

#include "runtime/core/rng.hpp"
#include "runtime/genome/graph/codec.hpp"
#include "runtime/genome/graph/graph_variation.hpp"

namespace esc::genome::graph {
namespace {

GraphOperators busy() {
  GraphOperators ops;
  ops.mutate_only_prob = 0.25;
  ops.mate_only_prob = 0.2;
  ops.mate_multipoint_prob = 0.6;
  ops.weight_mut_prob = 0.8;
  ops.weight_mut_power = 2.5;
  ops.add_node_prob = 0.3;
  ops.add_link_prob = 0.3;
  ops.newlink_tries = 20;
  ops.new_link_weight = 1.0;
  ops.toggle_enable_prob = 0.1;
  ops.reenable_prob = 0.1;
  return ops;
}

const GraphSpace kSpace{3, 2, Activation::Tanh, {}};

Graph decoded(const Genome& genome) {
  Graph g;
  EXPECT_EQ(decode(genome, g), "");
  return g;
}

TEST(GraphVariation, FirstGenomesAreTheStartWithFreshWeights) {
  GraphOperators ops = busy();
  ops.start_hidden = 1;
  const GraphVariation v(ops, kSpace);
  Rng rng(1);
  const std::vector<Genome> first = v.first(5, rng);
  ASSERT_EQ(first.size(), 5U);
  for (const Genome& genome : first) {
    EXPECT_EQ(v.misfit(genome), "");
    const Graph g = decoded(genome);
    EXPECT_EQ(count_nodes(g, NodeKind::Hidden), 1U);
    EXPECT_EQ(g.links.size(), 4U + 2U);   // 3 inputs and the bias into the hidden node, it into 2 outputs
    for (const NodeGene& n : g.nodes) {
      if (n.kind == NodeKind::Output) {
        EXPECT_EQ(n.activation, Activation::Tanh);
      }
    }
    for (const LinkGene& l : g.links) EXPECT_LE(std::abs(l.weight), kStartWeight);
  }
  EXPECT_NE(first[0], first[1]);
  EXPECT_NE(v.misfit(std::vector<double>{1.0, 2.0}), "");
  const GraphVariation wider(ops, GraphSpace{4, 2, Activation::Tanh, {}});
  EXPECT_NE(wider.misfit(first[0]).find("3 inputs and 2 outputs, not 4 and 2"), std::string::npos);
  EXPECT_THROW(GraphVariation(ops, GraphSpace{}), std::invalid_argument);
}

TEST(GraphVariation, ChildrenGrowAndNumberNewStructurePastTheirParents) {
  GraphVariation v(busy(), kSpace);
  Rng rng(2);
  std::vector<Genome> population = v.first(20, rng);
  EXPECT_THROW(v.cross_and_mutate(population[0], population[1], rng), std::logic_error);
  std::size_t grown = 0;
  for (int generation = 0; generation < 15; ++generation) {
    Id innovation = 1;
    for (const Genome& genome : population) innovation = std::max(innovation, next_innovation(decoded(genome)));
    v.begin(population);
    std::vector<Genome> children;
    for (std::size_t i = 0; i + 1 < population.size(); i += 2) {
      Genome a = population[i], b = population[i + 1];
      v.cross_and_mutate(a, b, rng);
      children.push_back(a);
      children.push_back(b);
    }
    children.push_back(v.mutate_one(population.back(), rng));
    children.push_back(v.mutate_one(population.front(), rng));
    // New links are numbered from the parents' counter on; the same new link in one
    // generation has one number.
    std::vector<std::pair<Id, Id>> seen_pairs;
    std::vector<Id> seen_numbers;
    for (const Genome& child : children) {
      ASSERT_EQ(v.misfit(child), "");
      const Graph g = decoded(child);
      grown += count_nodes(g, NodeKind::Hidden);
      for (const LinkGene& l : g.links) {
        if (l.innovation < innovation) continue;
        const auto at = std::find(seen_numbers.begin(), seen_numbers.end(), l.innovation);
        if (at != seen_numbers.end()) {
          EXPECT_EQ(seen_pairs[static_cast<std::size_t>(at - seen_numbers.begin())], std::make_pair(l.in, l.out));
        } else {
          seen_numbers.push_back(l.innovation);
          seen_pairs.emplace_back(l.in, l.out);
        }
      }
    }
    population.assign(children.begin(), children.begin() + 20);
  }
  EXPECT_GT(grown, 0U);
}

TEST(GraphVariation, TheSameDrawsGiveTheSameChildren) {
  const auto breed = [](std::uint64_t seed) {
    GraphVariation v(busy(), kSpace);
    Rng rng(seed);
    std::vector<Genome> population = v.first(10, rng);
    for (int generation = 0; generation < 8; ++generation) {
      v.begin(population);
      for (std::size_t i = 0; i + 1 < population.size(); i += 2) v.cross_and_mutate(population[i], population[i + 1], rng);
    }
    return population;
  };
  EXPECT_EQ(breed(4), breed(4));
  EXPECT_NE(breed(4), breed(5));
}

TEST(GraphVariation, TypicalSizeCountsAGrownNetwork) {
  // 3 inputs, a bias and 2 outputs: 16 links and 8 nodes once grown.
  EXPECT_EQ(typical_encoded_size(kSpace), encoded_size(8, 16));
}

}  // namespace
}  // namespace esc::genome::graph
