// The tree kind's operators (runtime/genome/tree/tree_operators.hpp), apart from GP: their
// defaults are the paper's, their check refuses what GP refused with GP's words, and their
// mutation mix is the one GP breeds with, so that a tree varied by NSGA-II or MAP-Elites is
// varied as GP varies it.
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "runtime/evo/gp/gp.hpp"
#include "runtime/genome/tree/init.hpp"
#include "runtime/genome/tree/tree_operators.hpp"
#include "runtime/genome/tree/tree_variation.hpp"
#include "tests/gp/helpers.hpp"

namespace esc::genome::tree {
namespace {

std::string refusal(auto&& make) {
  try {
    make();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return {};
}

TEST(TreeOperators, DefaultsAreThePapersAndGpExtendsThem) {
  const TreeOperators o;
  EXPECT_EQ((std::vector{o.crossover, o.subtree_mutation, o.point_mutation, o.hoist_mutation, o.internal_bias}),
            (std::vector{0.8, 0.05, 0.05, 0.05, 0.9}));
  EXPECT_EQ((std::vector{o.max_depth, o.max_size, o.init_min_depth, o.init_max_depth, o.mutation_depth}),
            (std::vector{12, 100, 2, 6, 4}));
  const evo::gp::GpSettings gp;
  EXPECT_EQ(gp.max_depth, o.max_depth);
  EXPECT_EQ(gp.population, 150);
  EXPECT_EQ(gp.limits().max_size, 100);
}

TEST(TreeOperators, RefuseWhatGpRefusedInGpsWordsWithoutGpsOwnSettings) {
  const PrimitiveSet set = test::number_set();
  const auto bad = [](auto change) {
    evo::gp::GpSettings s;
    change(s);
    return s;
  };
  for (const evo::gp::GpSettings& s :
       {bad([](auto& s) { s.crossover = 1.5; }), bad([](auto& s) { s.max_depth = 41; }),
        bad([](auto& s) { s.init_min_depth = 7; }), bad([](auto& s) { s.erc_sigma = -1.0; }),
        bad([](auto& s) { s.subtree_mutation = 0.5; })}) {
    const std::string by_gp = refusal([&] { (void)evo::gp::GeneticProgramming(s, set); });
    ASSERT_FALSE(by_gp.empty());
    EXPECT_EQ(refusal([&] { check_operators(s, set); }), by_gp);
    EXPECT_EQ(refusal([&] { (void)TreeVariation(s, set); }), by_gp);
  }
  // GP's own settings are GP's: the tree kind varies trees for any population.
  evo::gp::GpSettings s;
  s.population = 0;
  EXPECT_NE(refusal([&] { (void)evo::gp::GeneticProgramming(s, set); }), "");
  EXPECT_EQ(refusal([&] { check_operators(s, set); }), "");
}

TEST(TreeOperators, TheMutationMixSplitsTheDrawAsGpDid) {
  const PrimitiveSet set = test::number_set();
  TreeOperators o;
  o.subtree_mutation = 0.2;
  o.point_mutation = 0.3;
  o.hoist_mutation = 0.1;
  Rng grow_rng(3, {1});
  const Tree a = full(set, set.root(), 4, grow_rng);
  // Above every mutation's share: a copy, drawing nothing.
  Rng r1(5, {2});
  EXPECT_EQ(mutate(a, o, set, 0.95, 0.3, r1), a);
  Rng r2(5, {2});
  EXPECT_EQ(r1.next(), r2.next());
  // `edge` is what crossover took before the mutations: u just above it is subtree mutation,
  // just above edge + 0.2 point mutation, both as their own operators would.
  Rng s1(7, {4}), s2(7, {4});
  EXPECT_EQ(mutate(a, o, set, 0.31, 0.3, s1), subtree_mutation(a, set, o.limits(), o.mutation_depth, s2));
  Rng p1(7, {4}), p2(7, {4});
  EXPECT_EQ(mutate(a, o, set, 0.51, 0.3, p1), point_mutation(a, set, o.erc_sigma, p2));
  Rng h1(7, {4}), h2(7, {4});
  EXPECT_EQ(mutate(a, o, set, 0.81, 0.3, h1), hoist_mutation(a, set, h2));
}

}  // namespace
}  // namespace esc::genome::tree
