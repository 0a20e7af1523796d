// The phenotype on hand-built nets: values computed by hand, the steepened sigmoid, the
// one-step delay a hidden layer (or a recurrent link) puts between input and output in
// step mode, relaxation for classification, and reset().
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <new>

#include "runtime/genome/graph/network.hpp"

// Every allocation in this test program is counted, to show a network allocates nothing
// once built.
namespace {
std::size_t allocations = 0;
}  // namespace

void* operator new(std::size_t n) {
  ++allocations;
  if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace esc::genome::graph {
namespace {

// in 1, in 2, bias 3, output 4, hidden 5: all linear unless told.
Graph chain(Activation a = Activation::Linear) {
  Graph g;
  g.nodes = {{1, NodeKind::Input, a}, {2, NodeKind::Input, a}, {3, NodeKind::Bias, a}, {4, NodeKind::Output, a},
             {5, NodeKind::Hidden, a}};
  g.links = {{1, 5, 2.0, true, 1}, {5, 4, 3.0, true, 2}, {2, 4, 1.0, false, 3}};
  return g;
}

TEST(Network, NeatsSteepenedSigmoid) {
  EXPECT_DOUBLE_EQ(activate(Activation::NeatSigmoid, 0.0), 0.5);
  EXPECT_DOUBLE_EQ(activate(Activation::NeatSigmoid, 1.0), 1.0 / (1.0 + std::exp(-4.924273)));
  EXPECT_DOUBLE_EQ(activate(Activation::Sigmoid, 1.0), 1.0 / (1.0 + std::exp(-1.0)));
  EXPECT_DOUBLE_EQ(activate(Activation::Tanh, 0.3), std::tanh(0.3));
  EXPECT_DOUBLE_EQ(activate(Activation::Linear, -7.5), -7.5);
}

TEST(Network, AHiddenNodeDelaysTheOutputByOneStep) {
  Network net(chain());
  EXPECT_EQ(net.depth(), 2);
  // First step: the output turns on at the second pass, from the hidden node's first value.
  ASSERT_TRUE(net.step(std::vector<double>{1.0, 9.0}));
  EXPECT_DOUBLE_EQ(net.output()[0], 6.0);   // 3 x (2 x 1); the disabled link 2 -> 4 is not there
  // Later steps take one pass: the output reads what the hidden node held before it.
  ASSERT_TRUE(net.step(std::vector<double>{2.0, 0.0}));
  EXPECT_DOUBLE_EQ(net.output()[0], 6.0);
  ASSERT_TRUE(net.step(std::vector<double>{0.5, 0.0}));
  EXPECT_DOUBLE_EQ(net.output()[0], 12.0);
  net.reset();
  EXPECT_DOUBLE_EQ(net.output()[0], 0.0);
  ASSERT_TRUE(net.step(std::vector<double>{0.5, 0.0}));
  EXPECT_DOUBLE_EQ(net.output()[0], 3.0);
}

TEST(Network, RelaxSettlesAFeedForwardNet) {
  Network net(chain());
  ASSERT_TRUE(net.relax(std::vector<double>{1.0, 0.0}));
  EXPECT_DOUBLE_EQ(net.output()[0], 6.0);
  ASSERT_TRUE(net.relax(std::vector<double>{2.0, 0.0}));   // no reset: still settles to the new input
  EXPECT_DOUBLE_EQ(net.output()[0], 12.0);
}

TEST(Network, ARecurrentLinkIsReadOneStepLate) {
  Graph g = chain();
  g.links = {{1, 4, 1.0, true, 1}, {4, 4, 0.5, true, 2}};   // out_t = x_t + 0.5 out_{t-1}
  Network net(g);
  ASSERT_TRUE(net.step(std::vector<double>{1.0, 0.0}));
  EXPECT_DOUBLE_EQ(net.output()[0], 1.0);
  ASSERT_TRUE(net.step(std::vector<double>{1.0, 0.0}));
  EXPECT_DOUBLE_EQ(net.output()[0], 1.5);
  ASSERT_TRUE(net.step(std::vector<double>{0.0, 0.0}));
  EXPECT_DOUBLE_EQ(net.output()[0], 0.75);
}

TEST(Network, AHandBuiltXorSolution) {
  // out = step(x1 + x2 - 2 h - 0.5), h = step(x1 + x2 - 1.5), steep sigmoids standing in for steps.
  Graph g;
  const Activation s = Activation::NeatSigmoid;
  g.nodes = {{1, NodeKind::Input, s}, {2, NodeKind::Input, s}, {3, NodeKind::Bias, s}, {4, NodeKind::Output, s},
             {5, NodeKind::Hidden, s}};
  g.links = {{1, 4, 10.0, true, 1}, {2, 4, 10.0, true, 2}, {3, 4, -5.0, true, 3},
             {1, 5, 10.0, true, 4}, {2, 5, 10.0, true, 5}, {3, 5, -15.0, true, 6}, {5, 4, -20.0, true, 7}};
  Network net(g);
  const double patterns[4][2] = {{0, 0}, {0, 1}, {1, 0}, {1, 1}};
  const bool expected[4] = {false, true, true, false};
  for (int p = 0; p < 4; ++p) {
    net.reset();
    ASSERT_TRUE(net.relax(patterns[p]));
    EXPECT_EQ(net.output()[0] >= 0.5, expected[p]) << p;
  }
}

TEST(Network, StepsRelaxationsAndResetsAllocateNothing) {
  Graph g = chain(Activation::NeatSigmoid);
  g.links.push_back({4, 4, 0.5, true, 4});   // a recurrent link too
  Network net(g);
  const std::array<double, 2> x = {0.25, -1.0};
  const std::size_t before = allocations;
  for (int t = 0; t < 100; ++t) {
    if (t % 10 == 0) net.reset();
    ASSERT_TRUE(t % 3 == 0 ? net.relax(x) : net.step(x));
  }
  EXPECT_EQ(allocations, before);
}

TEST(Network, AnOutputNoPathReachesNeverTurnsOn) {
  Graph g = chain();
  g.links[1].enabled = false;   // 5 -> 4 off: nothing reaches the output
  Network net(g);
  EXPECT_FALSE(net.step(std::vector<double>{1.0, 1.0}));
  EXPECT_DOUBLE_EQ(net.output()[0], 0.0);
}

}  // namespace
}  // namespace esc::genome::graph
