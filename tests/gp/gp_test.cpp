// The GP algorithm: settings, selection with parsimony, elitism, determinism (also across
// thread counts), and runs whose fitness improves.
#include <cmath>

#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include "runtime/evo/gp/gp.hpp"
#include "runtime/genome/tree/program.hpp"
#include "tests/gp/helpers.hpp"

namespace esc::evo::gp {
namespace {

using namespace genome::tree;

using expr::Op;

std::string settings_error(GpSettings s, PrimitiveSet set = test::wheels_set()) {
  try {
    GeneticProgramming gp(s, std::move(set));
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(GpSettings, RejectsImpossibleSettings) {
  GpSettings s;
  EXPECT_EQ(settings_error(s), "");
  s.population = 0;
  EXPECT_NE(settings_error(s).find("population"), std::string::npos);
  s = {};
  s.elitism = 151;
  EXPECT_NE(settings_error(s).find("elitism"), std::string::npos);
  s = {};
  s.crossover = 0.9;
  s.subtree_mutation = 0.2;
  EXPECT_NE(settings_error(s).find("sum to"), std::string::npos);
  s = {};
  s.max_depth = 1;  // a Wheels tree needs depth 2
  s.init_min_depth = s.init_max_depth = 1;
  EXPECT_NE(settings_error(s).find("max_depth must be in [2, 40]"), std::string::npos) << settings_error(s);
  s = {};
  s.max_size = 2;
  EXPECT_NE(settings_error(s).find("max_size must be at least 3"), std::string::npos);
  s = {};
  s.init_max_depth = 20;
  EXPECT_NE(settings_error(s).find("init depths"), std::string::npos);
}

Individual sized(const PrimitiveSet& set, std::initializer_list<test::Tok> toks, double fitness) {
  return {test::postfix(set, toks), fitness};
}

TEST(Selection, ParsimonyBreaksTiesBySize) {
  const PrimitiveSet set = test::number_set();
  const std::vector<Individual> pop = {
      sized(set, {"ir[0]", "ir[1]", "+", "ir[2]", "*"}, 1.0),  // 5 nodes
      sized(set, {"ir[0]"}, 1.0),                              // 1 node, same fitness
  };
  EXPECT_TRUE(better(pop[1], pop[0]));
  EXPECT_FALSE(better(pop[0], pop[1]));
  Rng rng(1);
  int small_wins = 0;
  for (int k = 0; k < 1000; ++k) small_wins += tournament(pop, 2, rng) == 1 ? 1 : 0;
  // The big tree wins only when drawn twice (probability 1/4).
  EXPECT_NEAR(small_wins, 750, 60);
  for (int k = 0; k < 100; ++k) EXPECT_EQ(tournament(pop, 40, rng), 1U);
  // Fitness comes first.
  std::vector<Individual> fitter = pop;
  fitter[0].fitness = 1.5;
  EXPECT_TRUE(better(fitter[0], fitter[1]));
  EXPECT_EQ(ranking(fitter).front(), 0U);
  EXPECT_EQ(ranking(pop).front(), 1U);
  // NaN ranks last.
  fitter[0].fitness = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(ranking(fitter).front(), 1U);
}

// Maximise -mean |f(x) - target(x)| over x = ir[0] in [-1, 1].
double regression_fitness(const Tree& t, const PrimitiveSet& set) {
  const FlatProgram p = compile(t, set);
  FlatProgram::Stack stack{};
  expr::Frame f{};
  double err = 0.0;
  for (int k = 0; k <= 20; ++k) {
    const double x = -1.0 + 0.1 * k;
    f[expr::slot::ir] = x;
    err += std::abs(p.run(f, stack).value - (x * x + 0.5 * x));
  }
  return -err / 21.0;
}

PrimitiveSet regression_set() {
  return PrimitiveSet({prim::function(Op::Add), prim::function(Op::Sub), prim::function(Op::Mul),
                       prim::function(Op::Div), *prim::observable("ir[0]"), prim::erc(-1, 1)},
                      Type::Number);
}

struct RunResult {
  std::vector<Individual> population;
  std::vector<double> best;  // per generation
};

// A whole run; evaluation and breeding in parallel with `threads` workers.
RunResult run_regression(std::uint64_t seed, int generations, int threads) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                            static_cast<std::size_t>(threads));
  GpSettings s;
  s.population = 120;
  s.tournament = 4;
  s.elitism = 2;
  s.max_depth = 8;
  s.max_size = 40;
  s.init_max_depth = 4;
  const GeneticProgramming gp(s, regression_set());
  Rng init(seed, {0, static_cast<std::uint64_t>(Stream::Init)});
  RunResult r{gp.initial(init), {}};
  for (int g = 0;; ++g) {
    tbb::parallel_for(std::size_t{0}, r.population.size(), [&](std::size_t i) {
      r.population[i].fitness = regression_fitness(r.population[i].tree, gp.primitives());
    });
    r.best.push_back(r.population[ranking(r.population).front()].fitness);
    if (g == generations) break;
    Rng breed(seed, {0, static_cast<std::uint64_t>(g), static_cast<std::uint64_t>(Stream::Breed)});
    // Breed in parallel through offspring(); must equal gp.breed().
    const std::uint64_t base = Rng(breed).next();
    std::vector<Individual> next(r.population.size());
    const auto order = ranking(r.population);
    for (std::size_t k = 0; k < static_cast<std::size_t>(s.elitism); ++k) next[k] = r.population[order[k]];
    tbb::parallel_for(static_cast<std::size_t>(s.elitism), next.size(),
                      [&](std::size_t i) { next[i] = gp.offspring(r.population, base, i); });
    std::vector<Individual> serial = gp.breed(r.population, breed);
    for (std::size_t i = 0; i < next.size(); ++i) EXPECT_EQ(next[i].tree, serial[i].tree);
    r.population = std::move(next);
  }
  return r;
}

TEST(GeneticProgramming, InitialPopulationIsValid) {
  GpSettings s;
  s.population = 500;
  const GeneticProgramming gp(s, test::action_set());
  Rng rng(3);
  const auto pop = gp.initial(rng);
  ASSERT_EQ(pop.size(), 500U);
  for (const Individual& ind : pop) {
    EXPECT_TRUE(well_typed(ind.tree, gp.primitives(), Type::Action));
    EXPECT_LE(depth(ind.tree), s.init_max_depth);
    EXPECT_LE(static_cast<int>(ind.tree.size()), s.max_size);
  }
}

TEST(GeneticProgramming, BreedKeepsElitesTypesAndLimits) {
  GpSettings s;
  s.population = 200;
  s.elitism = 3;
  s.max_depth = 9;
  s.max_size = 50;
  for (const PrimitiveSet& set : test::all_sets()) {
    const GeneticProgramming gp(s, set);
    Rng rng(8, {index_of(set.root())});
    auto pop = gp.initial(rng);
    for (int g = 0; g < 10; ++g) {
      for (std::size_t i = 0; i < pop.size(); ++i)
        pop[i].fitness = -static_cast<double>((pop[i].tree.size() * 7919 + i) % 13);
      const auto order = ranking(pop);
      const auto next = gp.breed(pop, rng);
      ASSERT_EQ(next.size(), pop.size());
      for (int k = 0; k < s.elitism; ++k) EXPECT_EQ(next[static_cast<std::size_t>(k)].tree, pop[order[static_cast<std::size_t>(k)]].tree);
      for (const Individual& ind : next) {
        ASSERT_EQ(check(ind.tree, set, set.root()), "");
        ASSERT_LE(depth(ind.tree), s.max_depth);
        ASSERT_LE(static_cast<int>(ind.tree.size()), s.max_size);
      }
      pop = next;
    }
  }
}

TEST(GeneticProgramming, SameSeedSameRunForAnyThreadCount) {
  const RunResult one = run_regression(11, 6, 1);
  const RunResult two = run_regression(11, 6, 2);
  ASSERT_EQ(one.population.size(), two.population.size());
  for (std::size_t i = 0; i < one.population.size(); ++i) {
    EXPECT_EQ(one.population[i].tree, two.population[i].tree);
    EXPECT_EQ(one.population[i].fitness, two.population[i].fitness);
  }
  EXPECT_EQ(one.best, two.best);
  const RunResult other = run_regression(12, 6, 2);
  EXPECT_NE(other.best, one.best);
}

TEST(GeneticProgramming, SymbolicRegressionImproves) {
  const RunResult r = run_regression(5, 30, 2);
  // Elitism with a deterministic fitness: the best never gets worse.
  for (std::size_t g = 1; g < r.best.size(); ++g) EXPECT_GE(r.best[g], r.best[g - 1]);
  EXPECT_GT(r.best.back(), r.best.front());
  EXPECT_GT(r.best.back(), -0.05) << "x^2 + 0.5x fitted to within 0.05 on average";
}

}  // namespace
}  // namespace esc::evo::gp
