// Property tests: after every operator, over thousands of random trees from many seeds,
// trees stay well typed, within the depth and size limits, with consistent lengths.
#include <algorithm>

#include <gtest/gtest.h>

#include "runtime/genome/tree/init.hpp"
#include "runtime/genome/tree/operators.hpp"
#include "tests/gp/helpers.hpp"

namespace esc::genome::tree {
namespace {

constexpr Limits kLimits{8, 60};

void expect_valid(const Tree& t, const PrimitiveSet& set, const char* op, std::uint64_t seed) {
  ASSERT_EQ(check(t, set, set.root()), "") << op << " seed " << seed;
  ASSERT_LE(depth(t), kLimits.max_depth) << op << " seed " << seed;
  ASSERT_LE(static_cast<int>(t.size()), kLimits.max_size) << op << " seed " << seed;
  Tree copy = t;
  ASSERT_TRUE(update_lengths(copy));
  ASSERT_EQ(copy, t) << op << " seed " << seed;
}

TEST(Operators, EveryOperatorKeepsTypesAndLimits) {
  std::size_t trees = 0, changed = 0;
  for (const PrimitiveSet& set : test::all_sets()) {
    for (std::uint64_t seed = 0; seed < 12; ++seed) {
      Rng rng(seed, {21, index_of(set.root())});
      std::vector<Tree> pop = ramped_half_and_half(set, 30, 2, 6, kLimits.max_size, rng);
      for (const Tree& t : pop) expect_valid(t, set, "init", seed);
      for (int step = 0; step < 300; ++step) {
        const Tree& a = pop[rng.below(pop.size())];
        const Tree& b = pop[rng.below(pop.size())];
        const char* names[] = {"crossover", "subtree", "point", "hoist"};
        const std::uint64_t which = rng.below(4);
        Tree c;
        switch (which) {
          case 0: c = crossover(a, b, set, kLimits, 0.9, rng); break;
          case 1: c = subtree_mutation(a, set, kLimits, 4, rng); break;
          case 2: c = point_mutation(a, set, 0.1, rng); break;
          default: c = hoist_mutation(a, set, rng); break;
        }
        expect_valid(c, set, names[which], seed);
        changed += c != a ? 1 : 0;
        ++trees;
        pop[rng.below(pop.size())] = std::move(c);
      }
    }
  }
  EXPECT_GE(trees, 14000U);
  EXPECT_GT(changed, trees * 3 / 4);  // operators do change trees
}

TEST(Operators, CrossoverSwapsOnlySameTypedSubtrees) {
  for (const PrimitiveSet& set : test::all_sets()) {
    for (std::uint64_t seed = 0; seed < 200; ++seed) {
      Rng rng(seed, {22});
      const Tree a = grow(set, set.root(), 6, rng);
      const Tree b = grow(set, set.root(), 6, rng);
      const auto p = crossover_points(a, b, set, kLimits, 0.9, rng);
      if (!p) continue;
      const auto [i, j] = *p;
      ASSERT_EQ(a.nodes[i].type, b.nodes[j].type);
      const Tree c = splice(a, i, b, j);
      // The child is a's prefix, b's subtree, a's suffix, node for node (lengths aside).
      const std::size_t a0 = a.begin_of(i), b0 = b.begin_of(j), lb = b.nodes[j].length;
      ASSERT_EQ(c.size(), a.size() - a.nodes[i].length + lb);
      for (std::size_t k = 0; k < a0; ++k) EXPECT_EQ(c.nodes[k], a.nodes[k]);
      for (std::size_t k = 0; k < lb; ++k) EXPECT_EQ(c.nodes[a0 + k], b.nodes[b0 + k]);
      for (std::size_t k = a0 + lb; k < c.size(); ++k) {
        EXPECT_EQ(c.nodes[k].prim, a.nodes[k - lb + a.nodes[i].length].prim);
        EXPECT_EQ(c.nodes[k].value, a.nodes[k - lb + a.nodes[i].length].value);
      }
      ASSERT_EQ(check(c, set, set.root()), "");
    }
  }
}

TEST(Operators, CrossoverRefusesMovesBeyondTheLimits) {
  const PrimitiveSet set = test::number_set();
  Rng rng(5);
  const Tree big = full(set, Type::Number, 7, rng);
  const Tree small = grow(set, Type::Number, 2, rng);
  for (int k = 0; k < 200; ++k) {
    const Tree c = crossover(small, big, set, Limits{3, 7}, 0.9, rng);
    EXPECT_LE(depth(c), 3);
    EXPECT_LE(c.size(), 7U);
  }
}

TEST(Operators, PointMutationKeepsTheShape) {
  for (const PrimitiveSet& set : test::all_sets()) {
    for (std::uint64_t seed = 0; seed < 300; ++seed) {
      Rng rng(seed, {23});
      const Tree a = grow(set, set.root(), 5, rng);
      const Tree c = point_mutation(a, set, 0.1, rng);
      ASSERT_EQ(c.size(), a.size());
      int differ = 0;
      for (std::size_t k = 0; k < a.size(); ++k) {
        EXPECT_EQ(c.nodes[k].arity, a.nodes[k].arity);
        EXPECT_EQ(c.nodes[k].type, a.nodes[k].type);
        EXPECT_EQ(c.nodes[k].length, a.nodes[k].length);
        differ += c.nodes[k] != a.nodes[k] ? 1 : 0;
      }
      EXPECT_LE(differ, 1);
      ASSERT_EQ(check(c, set, set.root()), "");
    }
  }
}

TEST(Operators, HoistShrinksToAnInnerSubtree) {
  int hoisted = 0;
  for (const PrimitiveSet& set : test::all_sets()) {
    for (std::uint64_t seed = 0; seed < 300; ++seed) {
      Rng rng(seed, {24});
      const Tree a = grow(set, set.root(), 6, rng);
      const Tree c = hoist_mutation(a, set, rng);
      ASSERT_EQ(check(c, set, set.root()), "");
      EXPECT_LE(c.size(), a.size());
      EXPECT_LE(depth(c), depth(a));
      hoisted += c.size() < a.size() ? 1 : 0;
    }
  }
  EXPECT_GT(hoisted, 400);
}

TEST(Operators, ErcPointMutationMovesTheValue) {
  const PrimitiveSet set = test::number_set();
  const Tree a = test::postfix(set, {{"erc", 0.25}});
  Rng rng(9);
  const Tree c = point_mutation(a, set, 0.1, rng);
  EXPECT_EQ(c.nodes[0].prim, a.nodes[0].prim);
  EXPECT_NE(c.nodes[0].value, 0.25);
  EXPECT_LT(std::abs(c.nodes[0].value - 0.25), 1.5);  // 7.5 sigma of N(0, 0.2)
}

TEST(Operators, SameSeedSameChildren) {
  const PrimitiveSet set = test::wheels_set();
  Rng r0(1);
  const Tree a = grow(set, set.root(), 6, r0), b = grow(set, set.root(), 6, r0);
  Rng x(77), y(77);
  for (int k = 0; k < 50; ++k) {
    EXPECT_EQ(crossover(a, b, set, kLimits, 0.9, x), crossover(a, b, set, kLimits, 0.9, y));
    EXPECT_EQ(subtree_mutation(a, set, kLimits, 4, x), subtree_mutation(a, set, kLimits, 4, y));
  }
}

}  // namespace
}  // namespace esc::genome::tree
