// Tree layout, checks, and random initialisation over thousands of trees.
#include <limits>

#include <gtest/gtest.h>

#include "runtime/genome/tree/init.hpp"
#include "runtime/genome/tree/tree.hpp"
#include "tests/gp/helpers.hpp"

namespace esc::genome::tree {
namespace {

using test::postfix;

// Lengths and arities agree with a stack-based recount, and cached types with primitives.
void expect_consistent(const Tree& t, const PrimitiveSet& set) {
  Tree copy = t;
  ASSERT_TRUE(update_lengths(copy));
  EXPECT_EQ(copy, t);
  for (const Node& n : t.nodes) {
    EXPECT_EQ(n.arity, set[n.prim].arity);
    EXPECT_EQ(n.type, set[n.prim].result);
  }
}

TEST(Tree, LayoutOfAHandBuiltTree) {
  const PrimitiveSet set = test::wheels_set();
  // wheels(ir[0] + 0.5, if ir[1] > 0.2 then 1 else -1)
  const Tree t = postfix(set, {"ir[0]", {"erc", 0.5}, "+", "ir[1]", {"erc", 0.2}, ">",
                               {"erc", 1.0}, {"erc", -1.0}, "if", "wheels"});
  ASSERT_EQ(t.size(), 10U);
  EXPECT_EQ(t.nodes[9].length, 10U);
  EXPECT_EQ(t.nodes[2].length, 3U);
  EXPECT_EQ(t.nodes[8].length, 6U);
  const auto c = children(t, 9);
  EXPECT_EQ(c[0], 2U);
  EXPECT_EQ(c[1], 8U);
  const auto ci = children(t, 8);
  EXPECT_EQ(ci[0], 5U);
  EXPECT_EQ(ci[1], 6U);
  EXPECT_EQ(ci[2], 7U);
  EXPECT_EQ(t.begin_of(8), 3U);
  EXPECT_EQ(depth(t), 4);
  const auto lv = levels(t);
  EXPECT_EQ(lv[9], 1);
  EXPECT_EQ(lv[8], 2);
  EXPECT_EQ(lv[3], 4);
  EXPECT_EQ(subtree_depths(t)[8], 3);
  EXPECT_TRUE(well_typed(t, set, Type::Wheels));
  EXPECT_FALSE(well_typed(t, set, Type::Number));
}

TEST(Tree, CheckNamesWhatIsWrong) {
  const PrimitiveSet set = test::number_set();
  Tree t = postfix(set, {"ir[0]", {"erc", 0.5}, "+"});
  EXPECT_EQ(check(t, set, Type::Number), "");
  Tree bad_len = t;
  bad_len.nodes[2].length = 2;
  EXPECT_NE(check(bad_len, set, Type::Number).find("length"), std::string::npos);
  Tree bad_type = postfix(set, {"ir[0]", "ir[1]", "<"});
  bad_type.nodes.insert(bad_type.nodes.begin(), make_node(set, 0));  // dangling
  EXPECT_NE(check(bad_type, set, Type::Bool), "");
  // `+` given a Bool argument.
  Tree ill = postfix(set, {"ir[0]", "ir[1]", "+"});
  ill.nodes[0] = make_node(set, postfix(set, {"true"}).nodes[0].prim);
  EXPECT_NE(check(ill, set, Type::Number).find("argument 0 is a Bool, expected a Number"),
            std::string::npos)
      << check(ill, set, Type::Number);
  Tree nan = t;
  nan.nodes[1].value = std::numeric_limits<double>::infinity();
  EXPECT_NE(check(nan, set, Type::Number).find("not finite"), std::string::npos);
  EXPECT_NE(check(Tree{}, set, Type::Number), "");
}

TEST(Init, GrowAndFullRespectDepthForThousandsOfTrees) {
  for (const PrimitiveSet& set : test::all_sets()) {
    for (std::uint64_t seed = 0; seed < 300; ++seed) {
      Rng rng(seed, {11});
      const int d = 1 + static_cast<int>(seed % 8);
      const Tree g = grow(set, set.root(), d, rng);
      const Tree f = full(set, set.root(), d, rng);
      for (const Tree* t : {&g, &f}) {
        ASSERT_EQ(check(*t, set, set.root()), "") << "seed " << seed;
        expect_consistent(*t, set);
        EXPECT_LE(depth(*t), std::max(d, set.min_depth(set.root())));
      }
      // A numeric full tree reaches its depth (every type has functions at each level).
      if (set.root() == Type::Number) {
        EXPECT_EQ(depth(f), d) << "seed " << seed;
      }
    }
  }
}

TEST(Init, RampedHalfAndHalfWithinLimits) {
  for (const PrimitiveSet& set : test::all_sets()) {
    for (std::uint64_t seed = 0; seed < 20; ++seed) {
      Rng rng(seed, {12});
      const auto trees = ramped_half_and_half(set, 100, 2, 6, 40, rng);
      ASSERT_EQ(trees.size(), 100U);
      int deepest = 0;
      for (const Tree& t : trees) {
        ASSERT_EQ(check(t, set, set.root()), "");
        EXPECT_LE(depth(t), 6);
        EXPECT_LE(t.size(), 40U);
        deepest = std::max(deepest, depth(t));
      }
      EXPECT_GE(deepest, 5);  // the ramp reaches its deep end
    }
  }
}

TEST(Init, TinySizeLimitFallsBackToSmallestTree) {
  const PrimitiveSet set = test::wheels_set();
  Rng rng(3);
  for (const Tree& t : ramped_half_and_half(set, 50, 2, 8, 3, rng)) {
    EXPECT_TRUE(well_typed(t, set, Type::Wheels));
    EXPECT_EQ(t.size(), 3U);
  }
}

TEST(Init, SameSeedSameTrees) {
  const PrimitiveSet set = test::action_set();
  Rng a(42), b(42);
  EXPECT_EQ(ramped_half_and_half(set, 200, 2, 6, 60, a), ramped_half_and_half(set, 200, 2, 6, 60, b));
}

}  // namespace
}  // namespace esc::genome::tree
