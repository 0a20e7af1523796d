// Speciation and offspring counts on small hand-built populations, numbers chosen to be
// exact in binary so the counts are NEAT C++'s to the unit.
#include <gtest/gtest.h>

#include "runtime/evo/neat/speciation.hpp"

namespace esc::evo {
namespace {

Species species(std::vector<std::size_t> members, int age = 1, int last_improved = 0) {
  Species s;
  s.age = age;
  s.last_improved = last_improved;
  s.members = std::move(members);
  return s;
}

TEST(Speciation, SharedFitnessIsFitnessOverSpeciesSizeAndMembersAreRanked) {
  std::vector<Species> sp = {species({0, 1}), species({2, 3})};
  const std::vector<double> f = {1.0, 7.0, 4.0, 4.0};
  const Shares s = share_fitness(sp, f, NeatSettings{});
  EXPECT_EQ(sp[0].members, (std::vector<std::size_t>{1, 0}));   // the champion first
  EXPECT_EQ(sp[1].members, (std::vector<std::size_t>{2, 3}));   // ties keep their order
  EXPECT_EQ(s.shared, (std::vector<double>{0.5, 3.5, 2.0, 2.0}));
  EXPECT_EQ(sp[0].best_ever, 7.0);
  EXPECT_EQ(sp[0].last_improved, 1);
  EXPECT_EQ(s.parents, (std::vector<std::size_t>{1, 1}));   // floor(0.2 x 2 + 1)
}

TEST(Speciation, OffspringFollowNeatCsSkimAndShortfallRules) {
  std::vector<Species> sp = {species({0, 1}), species({2, 3})};
  const std::vector<double> f = {1.0, 7.0, 4.0, 4.0};
  const Shares s = share_fitness(sp, f, NeatSettings{});
  // Expected 1.75 + 0.25 and 1 + 1: the first species gets 1 (its carried fractions reach
  // exactly 1, and NEAT C++ adds only above 1), the second 2, and the shortfall of one goes
  // to the species expecting most.
  EXPECT_EQ(allocate_offspring(sp, s.shared, 4), (std::vector<int>{1, 3}));
}

TEST(Speciation, AStagnantSpeciesBreedsAtOnePercent) {
  NeatSettings set;
  set.dropoff_age = 15;
  // Age 20, last improved at 5, 6, 7: age - last + 1 - dropoff_age is 1, 0 (which NEAT C++
  // counts as 1) and -1.
  std::vector<Species> sp = {species({0, 1}, 20, 5), species({2, 3}, 20, 6), species({4, 5}, 20, 7)};
  for (Species& s : sp) s.best_ever = 100.0;
  const std::vector<double> f(6, 8.0);
  const Shares s = share_fitness(sp, f, set);
  EXPECT_DOUBLE_EQ(s.shared[0], 8.0 * 0.01 / 2.0);
  EXPECT_DOUBLE_EQ(s.shared[2], 8.0 * 0.01 / 2.0);
  EXPECT_DOUBLE_EQ(s.shared[4], 4.0);
  EXPECT_EQ(sp[0].last_improved, 5);   // 8 is no improvement on 100
}

TEST(Speciation, NegativeFitnessIsSharedShiftedButRecordedAsMeasured) {
  std::vector<Species> sp = {species({0, 1})};
  const Shares first = share_fitness(sp, std::vector<double>{-5.0, -7.0}, NeatSettings{});
  EXPECT_EQ(first.shared, (std::vector<double>{1.0, 0.0}));   // shifted by 7, over 2
  EXPECT_EQ(sp[0].best_ever, -5.0);
  EXPECT_EQ(sp[0].last_improved, 1);
  // A generation later every value has risen by 1 (the shift with them): an improvement.
  sp[0].age = 2;
  const Shares second = share_fitness(sp, std::vector<double>{-4.0, -6.0}, NeatSettings{});
  EXPECT_EQ(second.shared, (std::vector<double>{1.0, 0.0}));
  EXPECT_EQ(sp[0].best_ever, -4.0);
  EXPECT_EQ(sp[0].last_improved, 2);
}

TEST(Speciation, AllZeroFitnessGivesEachMemberOneOffspring) {
  std::vector<Species> sp = {species({0}), species({1, 2, 3})};
  const std::vector<double> f = {0.0, 0.0, 0.0, 0.0};
  const Shares s = share_fitness(sp, f, NeatSettings{});
  EXPECT_EQ(allocate_offspring(sp, s.shared, 4), (std::vector<int>{1, 3}));
}

TEST(Speciation, TheFirstCloseRepresentativeTakesTheGenome) {
  using namespace genome::graph;
  Graph a = minimal_graph(2, 1, Activation::NeatSigmoid);
  Graph b = a, c = a;
  b.links[0].weight = 1.0;   // distance 0.4 x 1 / 3 from a
  c.links[0].weight = 30.0;  // distance 0.4 x 30 / 3 = 4 from a
  const std::vector<const Graph*> reps = {&c, &a, &b};
  EXPECT_EQ(find_species(b, reps, {1.0, 1.0, 0.4}, 3.0), 1U);   // a before b
  const std::vector<const Graph*> far = {&c};
  EXPECT_EQ(find_species(a, far, {1.0, 1.0, 0.4}, 3.0), 1U);     // none: a new species
}

}  // namespace
}  // namespace esc::evo
