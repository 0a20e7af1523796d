#include "runtime/evo/es/es.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace esc::evo {
namespace {

double sphere(const std::vector<double>& x) {
  double s = 0.0;
  for (double v : x) s += v * v;
  return -s;  // maximised
}

double best_of(const std::vector<Individual>& pop) {
  double b = -std::numeric_limits<double>::infinity();
  for (const Individual& i : pop) b = std::max(b, i.fitness);
  return b;
}

// A generation loop like the lead's: breed, evaluate, select. Returns the best fitness.
double run_sphere(const EsSettings& s, std::size_t n, std::uint64_t seed, int generations) {
  const EvolutionStrategy es(s, n);
  Rng init(seed, {static_cast<std::uint64_t>(Stream::Init)});
  std::vector<Individual> parents = es.initial(init);
  for (Individual& p : parents) p.fitness = sphere(p.genes);
  for (int g = 0; g < generations; ++g) {
    Rng rng(seed, {static_cast<std::uint64_t>(Stream::Breed), static_cast<std::uint64_t>(g)});
    std::vector<Individual> kids = es.breed(parents, rng);
    for (Individual& k : kids) k.fitness = sphere(k.genes);
    parents = es.select(parents, kids);
  }
  return best_of(parents);
}

TEST(Es, InitialPopulationHasMuIndividualsInBounds) {
  EsSettings s;
  s.mu = 7;
  s.lower = -2.0;
  s.upper = 3.0;
  s.initial_sigma = 0.1;
  const EvolutionStrategy es(s, 12);
  Rng rng(42);
  const std::vector<Individual> pop = es.initial(rng);
  ASSERT_EQ(pop.size(), 7u);
  double lo = 1e9, hi = -1e9;
  for (const Individual& i : pop) {
    ASSERT_EQ(i.genes.size(), 12u);
    ASSERT_EQ(i.sigmas.size(), 12u);  // PerGene is the default
    for (double g : i.genes) {
      EXPECT_GE(g, -2.0);
      EXPECT_LT(g, 3.0);
      lo = std::min(lo, g);
      hi = std::max(hi, g);
    }
    for (double sg : i.sigmas) EXPECT_DOUBLE_EQ(sg, 0.5);  // 0.1 * (3 - -2)
  }
  EXPECT_LT(lo, -1.0);  // 84 uniform draws spread over the interval
  EXPECT_GT(hi, 2.0);

  s.step_sizes = StepSizes::One;
  const EvolutionStrategy one(s, 12);
  for (const Individual& i : one.initial(rng)) {
    EXPECT_EQ(i.genes.size(), 12u);
    ASSERT_EQ(i.sigmas.size(), 1u);
    EXPECT_DOUBLE_EQ(i.sigmas[0], 0.5);
  }
}

TEST(Es, BreedGivesLambdaOffspringOfTheRightShape) {
  EsSettings s;
  s.mu = 4;
  s.lambda = 20;
  for (StepSizes ss : {StepSizes::One, StepSizes::PerGene}) {
    for (Recombination r : {Recombination::Intermediate, Recombination::Discrete,
                            Recombination::None}) {
      s.step_sizes = ss;
      s.recombination = r;
      const EvolutionStrategy es(s, 9);
      Rng rng(3);
      const std::vector<Individual> kids = es.breed(es.initial(rng), rng);
      ASSERT_EQ(kids.size(), 20u);
      for (const Individual& k : kids) {
        EXPECT_EQ(k.genes.size(), 9u);
        EXPECT_EQ(k.sigmas.size(), ss == StepSizes::One ? 1u : 9u);
      }
    }
  }
}

TEST(Es, SameSeedGivesBitIdenticalOffspring) {
  for (Recombination r :
       {Recombination::Intermediate, Recombination::Discrete, Recombination::None}) {
    EsSettings s;
    s.mu = 5;
    s.lambda = 25;
    s.recombination = r;
    const EvolutionStrategy es(s, 30);
    Rng init(11);
    const std::vector<Individual> parents = es.initial(init);
    Rng a(99, {2, 7});
    Rng b(99, {2, 7});
    Rng c(99, {2, 8});
    const std::vector<Individual> ka = es.breed(parents, a);
    const std::vector<Individual> kb = es.breed(parents, b);
    const std::vector<Individual> kc = es.breed(parents, c);
    ASSERT_EQ(ka.size(), kb.size());
    bool differs = false;
    for (std::size_t i = 0; i < ka.size(); ++i) {
      EXPECT_EQ(ka[i].genes, kb[i].genes);  // exact, element by element
      EXPECT_EQ(ka[i].sigmas, kb[i].sigmas);
      differs = differs || ka[i].genes != kc[i].genes;
    }
    EXPECT_TRUE(differs) << "another stream must give other offspring";
  }
}

TEST(Es, WholeRunIsReproducible) {
  EsSettings s;
  s.mu = 5;
  s.lambda = 35;
  s.lower = -5.0;
  s.upper = 5.0;
  EXPECT_EQ(run_sphere(s, 6, 1234, 30), run_sphere(s, 6, 1234, 30));
  EXPECT_NE(run_sphere(s, 6, 1234, 30), run_sphere(s, 6, 1235, 30));
}

TEST(Es, EachParentIsFirstParentOfLambdaOverMuOffspring) {
  // Without recombination and with negligible steps, offspring k is parent k mod mu.
  EsSettings s;
  s.mu = 3;
  s.lambda = 15;
  s.recombination = Recombination::None;
  s.lower = -100.0;
  s.upper = 100.0;
  s.min_sigma = 0.0;
  const EvolutionStrategy es(s, 4);
  std::vector<Individual> parents(3);
  for (int p = 0; p < 3; ++p) {
    parents[p].genes.assign(4, 10.0 * p);
    parents[p].sigmas.assign(4, 1e-9);
  }
  Rng rng(5);
  const std::vector<Individual> kids = es.breed(parents, rng);
  ASSERT_EQ(kids.size(), 15u);
  for (std::size_t k = 0; k < kids.size(); ++k)
    for (double g : kids[k].genes) EXPECT_NEAR(g, 10.0 * static_cast<double>(k % 3), 1e-6);
}

// Parents with far-apart genes and steps too small to move them: recombination is then
// visible exactly in the offspring.
std::vector<Individual> distinct_parents(int mu, std::size_t n, std::size_t n_sigmas) {
  std::vector<Individual> parents(static_cast<std::size_t>(mu));
  for (int p = 0; p < mu; ++p) {
    for (std::size_t i = 0; i < n; ++i)
      parents[p].genes.push_back(1.0 + p + 0.001 * static_cast<double>(i));  // never 0
    parents[p].sigmas.assign(n_sigmas, 1e-300);
  }
  return parents;
}

TEST(Es, IntermediateRecombinationAveragesFirstParentAndAMate) {
  EsSettings s;
  s.mu = 4;
  s.lambda = 40;
  s.lower = -10.0;
  s.upper = 10.0;
  s.min_sigma = 0.0;
  const EvolutionStrategy es(s, 5);
  const std::vector<Individual> parents = distinct_parents(4, 5, 5);
  Rng rng(8);
  const std::vector<Individual> kids = es.breed(parents, rng);
  std::vector<int> mates(4, 0);
  for (std::size_t k = 0; k < kids.size(); ++k) {
    const Individual& a = parents[k % 4];
    int mate = -1;
    for (int m = 0; m < 4; ++m) {
      bool all = true;
      for (std::size_t i = 0; i < 5; ++i)
        all = all && kids[k].genes[i] == 0.5 * (a.genes[i] + parents[m].genes[i]);
      if (all) mate = m;
    }
    ASSERT_GE(mate, 0) << "offspring " << k << " is not a mean of its parent and a mate";
    ++mates[mate];
  }
  for (int m : mates) EXPECT_GT(m, 0) << "every parent is drawn as a mate sometimes";
}

TEST(Es, DiscreteRecombinationTakesEachGeneFromOneParent) {
  EsSettings s;
  s.mu = 2;
  s.lambda = 20;
  s.recombination = Recombination::Discrete;
  s.lower = -10.0;
  s.upper = 10.0;
  s.min_sigma = 0.0;
  const std::size_t n = 16;
  const EvolutionStrategy es(s, n);
  const std::vector<Individual> parents = distinct_parents(2, n, n);
  Rng rng(21);
  const std::vector<Individual> kids = es.breed(parents, rng);
  int mixed = 0;
  for (const Individual& k : kids) {
    int from0 = 0, from1 = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (k.genes[i] == parents[0].genes[i]) ++from0;
      else if (k.genes[i] == parents[1].genes[i]) ++from1;
      else ADD_FAILURE() << "gene " << i << " comes from neither parent";
    }
    if (from0 > 0 && from1 > 0) ++mixed;
  }
  EXPECT_GT(mixed, 5);  // a mate other than the first parent mixes the genes
}

TEST(Es, GenesStayInBoundsWithHugeSteps) {
  for (StepSizes ss : {StepSizes::One, StepSizes::PerGene}) {
    EsSettings s;
    s.mu = 5;
    s.lambda = 30;
    s.step_sizes = ss;
    s.lower = -1.0;
    s.upper = 1.0;
    s.initial_sigma = kMaxStepSize;   // the largest allowed
    const EvolutionStrategy es(s, 20);
    Rng rng(77);
    std::vector<Individual> parents = es.initial(rng);
    int edge_hits = 0;
    for (int g = 0; g < 100; ++g) {
      std::vector<Individual> kids = es.breed(parents, rng);
      for (Individual& k : kids) {
        for (double x : k.genes) {
          ASSERT_TRUE(std::isfinite(x));
          ASSERT_GE(x, -1.0);
          ASSERT_LE(x, 1.0);
          if (std::abs(x) == 1.0) ++edge_hits;
        }
        for (double sigma : k.sigmas) ASSERT_LE(sigma, kMaxStepSize * 2.0);   // capped at 1000 (HI - LO)
        k.fitness = rng.uniform();  // selection that keeps sigmas huge
      }
      parents = es.select(parents, kids);
    }
    EXPECT_LT(edge_hits, 10) << "reflection must not pile genes up on the bounds";
  }
}

TEST(Es, RefusesBoundsAndStepSizesWhoseArithmeticCouldOverflow) {
  EsSettings s;
  s.lower = -1e308;
  s.upper = 1e308;   // HI - LO is infinite: genes would be NaN
  EXPECT_THROW(EvolutionStrategy(s, 4), std::invalid_argument);
  s.lower = -kMaxGeneBound;
  s.upper = kMaxGeneBound;
  EXPECT_NO_THROW(EvolutionStrategy(s, 4));
  s.initial_sigma = kMaxStepSize * 1.5;
  EXPECT_THROW(EvolutionStrategy(s, 4), std::invalid_argument);
  s.initial_sigma = 0.1;
  s.min_sigma = 3 * kMaxGeneBound;   // wider than the interval
  EXPECT_THROW(EvolutionStrategy(s, 4), std::invalid_argument);
}

TEST(Es, StepsNeverFallBelowMinSigma) {
  EsSettings s;
  s.mu = 3;
  s.lambda = 12;
  s.initial_sigma = 1e-9;
  s.min_sigma = 1e-4;
  const EvolutionStrategy es(s, 6);
  Rng rng(4);
  const std::vector<Individual> kids = es.breed(es.initial(rng), rng);
  for (const Individual& k : kids)
    for (double sg : k.sigmas) EXPECT_GE(sg, 1e-4);
}

std::vector<Individual> with_fitness(std::initializer_list<double> f, double tag) {
  std::vector<Individual> v;
  for (double x : f) v.push_back({{tag + static_cast<double>(v.size())}, {1.0}, x});
  return v;
}

TEST(Es, CommaDropsAGreatParentPlusKeepsIt) {
  EsSettings s;
  s.mu = 2;
  s.lambda = 4;
  s.step_sizes = StepSizes::One;
  const std::vector<Individual> parents = with_fitness({100.0, 1.0}, 0.0);
  const std::vector<Individual> kids = with_fitness({3.0, 5.0, 4.0, 2.0}, 10.0);

  s.selection = Selection::Comma;
  const std::vector<Individual> comma = EvolutionStrategy(s, 1).select(parents, kids);
  ASSERT_EQ(comma.size(), 2u);
  EXPECT_EQ(comma[0].fitness, 5.0);
  EXPECT_EQ(comma[0].genes[0], 11.0);
  EXPECT_EQ(comma[1].fitness, 4.0);

  s.selection = Selection::Plus;
  const std::vector<Individual> plus = EvolutionStrategy(s, 1).select(parents, kids);
  ASSERT_EQ(plus.size(), 2u);
  EXPECT_EQ(plus[0].fitness, 100.0);
  EXPECT_EQ(plus[0].genes[0], 0.0);
  EXPECT_EQ(plus[1].fitness, 5.0);
}

TEST(Es, TiesKeepTheEarlierIndividual) {
  EsSettings s;
  s.mu = 3;
  s.lambda = 4;
  const std::vector<Individual> parents = with_fitness({1.0, 2.0, 1.0}, 0.0);
  const std::vector<Individual> kids = with_fitness({2.0, 1.0, 2.0, 2.0}, 10.0);

  s.selection = Selection::Plus;  // parents come first in the merged order
  const std::vector<Individual> plus = EvolutionStrategy(s, 1).select(parents, kids);
  ASSERT_EQ(plus.size(), 3u);
  EXPECT_EQ(plus[0].genes[0], 1.0);   // parent 1
  EXPECT_EQ(plus[1].genes[0], 10.0);  // offspring 0
  EXPECT_EQ(plus[2].genes[0], 12.0);  // offspring 2

  s.selection = Selection::Comma;
  const std::vector<Individual> comma = EvolutionStrategy(s, 1).select(parents, kids);
  ASSERT_EQ(comma.size(), 3u);
  EXPECT_EQ(comma[0].genes[0], 10.0);
  EXPECT_EQ(comma[1].genes[0], 12.0);
  EXPECT_EQ(comma[2].genes[0], 13.0);
}

TEST(Es, NanFitnessRanksLast) {
  EsSettings s;
  s.mu = 2;
  s.lambda = 3;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Individual> kids = with_fitness({nan, -5.0, 1.0}, 0.0);
  const std::vector<Individual> sel = EvolutionStrategy(s, 1).select({}, kids);
  ASSERT_EQ(sel.size(), 2u);
  EXPECT_EQ(sel[0].fitness, 1.0);
  EXPECT_EQ(sel[1].fitness, -5.0);
}

TEST(Es, SelectThrowsWithFewerThanMuCandidates) {
  EsSettings s;
  s.mu = 3;
  s.lambda = 3;
  const std::vector<Individual> kids = with_fitness({1.0, 2.0}, 0.0);
  EXPECT_THROW((void)EvolutionStrategy(s, 1).select({}, kids), std::invalid_argument);
  s.selection = Selection::Plus;
  const std::vector<Individual> parents = with_fitness({1.0}, 5.0);
  EXPECT_EQ(EvolutionStrategy(s, 1).select(parents, kids).size(), 3u);
}

TEST(Es, BreedRejectsMalformedParents) {
  EsSettings s;
  s.mu = 2;
  s.lambda = 4;
  const EvolutionStrategy es(s, 3);
  Rng rng(1);
  EXPECT_THROW((void)es.breed({}, rng), std::invalid_argument);
  std::vector<Individual> parents = es.initial(rng);
  parents[1].genes.pop_back();
  EXPECT_THROW((void)es.breed(parents, rng), std::invalid_argument);
}

// (10, 70)-ES on the 10-dimensional sphere in [-5, 5]: self-adaptation must shrink the
// steps as the population closes in (with steps floored at 1.0 it ends between -2 and -13).
// Measured on this implementation over seeds 1..30: the initial best is -65 at worst, the
// best after 200 generations -1e-23 at worst (one or per-gene step sizes), so asserting
// -1e-15 keeps a wide margin while demanding over 15 orders of magnitude.
TEST(Es, SelfAdaptationSolvesTheSphere) {
  EsSettings s;
  s.mu = 10;
  s.lambda = 70;
  s.lower = -5.0;
  s.upper = 5.0;
  s.initial_sigma = 0.1;
  s.min_sigma = 1e-12;
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const double best = run_sphere(s, 10, seed, 200);
    EXPECT_GT(best, -1e-15) << "seed " << seed;
  }
  s.step_sizes = StepSizes::One;
  EXPECT_GT(run_sphere(s, 10, 1, 200), -1e-15);
}

TEST(Es, InvalidSettingsThrowNamingTheSetting) {
  struct Case {
    std::function<void(EsSettings&)> edit;
    std::size_t n;
    std::string name;
  };
  const std::vector<Case> cases = {
      {[](EsSettings& s) { s.mu = 0; }, 5, "mu"},
      {[](EsSettings& s) { s.lambda = 0; }, 5, "lambda"},
      {[](EsSettings& s) { s.mu = 10, s.lambda = 5; }, 5, "lambda"},
      {[](EsSettings& s) { s.lower = 1.0, s.upper = 1.0; }, 5, "lower"},
      {[](EsSettings& s) { s.lower = 2.0, s.upper = -1.0; }, 5, "upper"},
      {[](EsSettings& s) { s.upper = std::numeric_limits<double>::quiet_NaN(); }, 5, "upper"},
      {[](EsSettings& s) { s.initial_sigma = 0.0; }, 5, "initial_sigma"},
      {[](EsSettings& s) { s.min_sigma = -1e-3; }, 5, "min_sigma"},
      {[](EsSettings&) {}, 0, "genome_size"},
  };
  for (const Case& c : cases) {
    EsSettings s;
    c.edit(s);
    try {
      const EvolutionStrategy es(s, c.n);
      ADD_FAILURE() << "no exception for a bad " << c.name;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(c.name), std::string::npos)
          << "message '" << e.what() << "' does not name " << c.name;
    }
  }
  // Plus selection allows lambda < mu.
  EsSettings plus;
  plus.selection = Selection::Plus;
  plus.mu = 10;
  plus.lambda = 5;
  EXPECT_NO_THROW(EvolutionStrategy(plus, 5));
}

}  // namespace
}  // namespace esc::evo
