// NEAT's operators on hand-built genomes: the innovation record shared within a generation
// and not across, add-node's split, add-link forward and recurrent, toggling, crossover on
// the paper's Figure 4 pair, and the compatibility distance computed by hand.
#include <gtest/gtest.h>

#include "runtime/genome/graph/crossover.hpp"
#include "runtime/genome/graph/distance.hpp"
#include "runtime/genome/graph/mutation.hpp"
#include "tests/genome_graph/figure4.hpp"

namespace esc::genome::graph {
namespace {

Graph xor_start() {
  Graph g = minimal_graph(2, 1, Activation::NeatSigmoid);
  for (std::size_t i = 0; i < g.links.size(); ++i) g.links[i].weight = 0.5 + static_cast<double>(i);
  return g;
}

TEST(AddNode, SplitsALinkIntoWeightOneAndTheOldWeight) {
  Graph g = xor_start();
  InnovationRecord record(next_innovation(g), next_node_id(g));
  Rng rng(3);
  ASSERT_TRUE(add_node(g, record, Activation::Tanh, rng));
  EXPECT_EQ(misfit(g), "");
  ASSERT_EQ(g.nodes.size(), 5U);
  EXPECT_EQ(g.nodes[4], (NodeGene{5, NodeKind::Hidden, Activation::Tanh}));
  ASSERT_EQ(g.links.size(), 5U);
  // The split link stays, disabled; never one from the bias (node 3).
  const auto split = std::find_if(g.links.begin(), g.links.end(), [](const LinkGene& l) { return !l.enabled; });
  ASSERT_NE(split, g.links.end());
  EXPECT_NE(split->in, 3);
  EXPECT_EQ(g.links[3], (LinkGene{split->in, 5, 1.0, true, 4}));
  EXPECT_EQ(g.links[4], (LinkGene{5, 4, split->weight, true, 5}));
  EXPECT_EQ(record.next_innovation(), 6);
  EXPECT_EQ(record.next_node(), 6);
}

TEST(InnovationRecord, TheSameSplitInOneGenerationGetsTheSameNumbers) {
  const Graph start = xor_start();
  InnovationRecord record(next_innovation(start), next_node_id(start));
  Graph a = start, b = start;
  Rng ra(11), rb(11);   // the same draws: the same link split in both
  ASSERT_TRUE(add_node(a, record, Activation::NeatSigmoid, ra));
  ASSERT_TRUE(add_node(b, record, Activation::NeatSigmoid, rb));
  EXPECT_EQ(a, b);
  EXPECT_EQ(record.next_node(), 6);   // one node id given out, not two
  // The next generation: the same split is a new innovation.
  record.next_generation();
  Graph c = start;
  Rng rc(11);
  ASSERT_TRUE(add_node(c, record, Activation::NeatSigmoid, rc));
  EXPECT_EQ(c.nodes.back().id, 6);
  EXPECT_EQ(c.links.back().innovation, 7);
}

TEST(InnovationRecord, TheSameNewLinkGetsTheSameInnovationAndWeight) {
  Graph start = xor_start();
  InnovationRecord split_record(next_innovation(start), next_node_id(start));
  Rng r0(5);
  ASSERT_TRUE(add_node(start, split_record, Activation::NeatSigmoid, r0));
  // Now one of the inputs is not linked to hidden node 5: a forward link can be added.
  InnovationRecord record(split_record.next_innovation(), split_record.next_node());
  Graph a = start, b = start;
  Rng ra(8), rb(8);
  ASSERT_TRUE(add_link(a, record, 0.0, 50, 10.0, ra));
  ASSERT_TRUE(add_link(b, record, 0.0, 50, 10.0, rb));
  EXPECT_EQ(a, b);
  EXPECT_EQ(record.next_innovation(), split_record.next_innovation() + 1);
  EXPECT_EQ(misfit(a), "");
}

TEST(AddLink, ForwardOnlyNeverMakesACycle) {
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    Graph g = xor_start();
    InnovationRecord record(next_innovation(g), next_node_id(g));
    Rng rng(seed);
    for (int k = 0; k < 6; ++k) {
      (void)add_node(g, record, Activation::NeatSigmoid, rng);
      (void)add_link(g, record, 0.0, 20, 10.0, rng);
    }
    ASSERT_EQ(misfit(g), "") << seed;
    for (const LinkGene& l : g.links) {
      if (!l.enabled) continue;
      Graph without = g;
      std::erase_if(without.links, [&](const LinkGene& o) { return o.innovation == l.innovation; });
      EXPECT_FALSE(is_recurrent(without, l.in, l.out)) << "seed " << seed << " link " << l.innovation;
    }
  }
}

TEST(AddLink, RecurOnlyMakesRecurrentLinks) {
  Graph g = xor_start();
  InnovationRecord record(next_innovation(g), next_node_id(g));
  Rng rng(3);
  ASSERT_TRUE(add_node(g, record, Activation::NeatSigmoid, rng));
  const Graph before = g;
  ASSERT_TRUE(add_link(g, record, 1.0, 50, 10.0, rng));
  ASSERT_EQ(g.links.size(), before.links.size() + 1);
  const LinkGene& added = g.links.back();
  EXPECT_TRUE(is_recurrent(before, added.in, added.out));
  EXPECT_LE(std::abs(added.weight), 10.0);
}

TEST(Toggle, NeverCutsTheOnlyEnabledLinkOutOfANode) {
  Graph g = testing::figure4_parent1();   // node 3's only link out is innovation 3
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    Graph t = g;
    Rng rng(seed);
    toggle_enable(t, rng);
    EXPECT_TRUE(t.links[2].enabled) << seed;
  }
  Graph r = g;
  reenable(r);
  EXPECT_TRUE(r.links[1].enabled);   // innovation 2, the first disabled
}

TEST(WeightMutation, ReplacementStaysInItsRangeAndPerturbationMovesEveryWeightBySmallSteps) {
  Graph g = testing::figure4_parent2();
  Rng rng(4);
  replace_weights(g, 1.0, rng);
  for (const LinkGene& l : g.links) EXPECT_LE(std::abs(l.weight), 1.0);
  const Graph before = g;
  mutate_weights(g, 2.5, rng);
  for (std::size_t i = 0; i < g.links.size(); ++i) {
    const double change = std::abs(g.links[i].weight - before.links[i].weight);
    EXPECT_LE(change, 2.5 + 1.0 + 1e-12);   // a replacement is within 2.5 of 0, the old within 1
  }
}

TEST(Crossover, Figure4TheFitterParentsDisjointAndExcessOnly) {
  const Graph p1 = testing::figure4_parent1(), p2 = testing::figure4_parent2();
  Rng rng(1);
  const Graph from_p2 = mate(p1, p2, 1.0, 2.0, Mating::Multipoint, rng);
  std::vector<Id> innovations;
  for (const LinkGene& l : from_p2.links) innovations.push_back(l.innovation);
  EXPECT_EQ(innovations, (std::vector<Id>{1, 2, 3, 4, 5, 6, 7, 9, 10}));
  EXPECT_EQ(from_p2.nodes.size(), 6U);
  EXPECT_EQ(misfit(from_p2), "");
  // Each matching link from one parent or the other; the disjoint ones are p2's own.
  for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(std::abs(from_p2.links[i].weight), p1.links[i].weight);
  EXPECT_EQ(from_p2.links[5], p2.links[5]);

  // Equal fitness: the smaller genome (p1, 6 links) counts as the fitter, as NEAT C++ does.
  const Graph tie = mate(p1, p2, 1.0, 1.0, Mating::Multipoint, rng);
  innovations.clear();
  for (const LinkGene& l : tie.links) innovations.push_back(l.innovation);
  EXPECT_EQ(innovations, (std::vector<Id>{1, 2, 3, 4, 5, 8}));
  EXPECT_EQ(tie.nodes.size(), 5U);   // hidden 6 is not reached
}

TEST(Crossover, AveragedMatchingLinksAndDisabledOnesMostlyStayDisabled) {
  const Graph p1 = testing::figure4_parent1(), p2 = testing::figure4_parent2();
  int disabled = 0;
  const int trials = 2000;
  for (int t = 0; t < trials; ++t) {
    Rng rng(static_cast<std::uint64_t>(t));
    const Graph c = mate(p1, p2, 2.0, 1.0, Mating::MultipointAverage, rng);
    ASSERT_EQ(c.links.size(), 6U);
    EXPECT_DOUBLE_EQ(c.links[0].weight, 0.0);   // (0.1 + -0.1) / 2
    EXPECT_TRUE(c.links[0].enabled);
    disabled += c.links[4].enabled ? 0 : 1;     // innovation 5: disabled in p2
  }
  EXPECT_NEAR(static_cast<double>(disabled) / trials, kKeepDisabled, 0.03);
}

TEST(Distance, Figure4ByHand) {
  const Graph p1 = testing::figure4_parent1(), p2 = testing::figure4_parent2();
  const Alignment a = align(p1, p2);
  EXPECT_EQ(a.matching, 5U);
  EXPECT_EQ(a.disjoint, 3U);   // 6 and 7 of p2, 8 of p1
  EXPECT_EQ(a.excess, 2U);     // 9 and 10
  EXPECT_NEAR(a.weight_difference, 0.2 + 0.4 + 0.6 + 0.8 + 1.0, 1e-12);
  // c1 E + c2 D + c3 W: 1 x 2 + 1 x 3 + 0.4 x 0.6, no division by the genome size.
  EXPECT_NEAR(compatibility(p1, p2, {1.0, 1.0, 0.4}), 5.24, 1e-12);
  EXPECT_NEAR(compatibility(p1, p2, {2.0, 0.5, 3.0}), 4.0 + 1.5 + 1.8, 1e-12);
  EXPECT_EQ(compatibility(p1, p1, {1.0, 1.0, 3.0}), 0.0);
  Graph empty = p1;
  empty.links.clear();
  EXPECT_EQ(compatibility(p1, empty, {1.0, 1.0, 3.0}), 6.0);   // all excess, no matching: W = 0
}

}  // namespace
}  // namespace esc::genome::graph
