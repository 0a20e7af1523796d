// The registry (runtime/evo/registry.hpp): every algorithm is found by the name scripts
// write, declares the genome kinds it evolves, and is its folder's value type erased once;
// CVT-MAP-Elites is MAP-Elites' value under another name with other options and defaults.
#include <gtest/gtest.h>

#include <algorithm>
#include <any>
#include <memory>
#include <string>
#include <vector>

#include "runtime/evo/es/es.hpp"
#include "runtime/evo/gp/gp.hpp"
#include "runtime/evo/map_elites/map_elites_optimizer.hpp"
#include "runtime/evo/registry.hpp"
#include "runtime/genome/tree/tree_space.hpp"
#include "tests/gp/helpers.hpp"

namespace esc::evo {
namespace {

using enum genome::GenomeKind;
using genome::GenomeKinds;

std::vector<std::string> keys(const Algorithm& a) {
  std::vector<std::string> k;
  for (const AlgorithmOption& o : a.options()) k.emplace_back(o.key);
  return k;
}

TEST(Registry, FindsEveryAlgorithmByItsNameWithTheKindsItDeclares) {
  const std::vector<std::pair<std::string, GenomeKinds>> expected = {
      {"es", {Vector}},
      {"gp", {Tree}},
      {"cmaes", {Vector}},
      {"nsga2", {Vector, Tree, Graph}},
      {"map_elites", {Vector, Tree, Graph}},
      {"cvt_map_elites", {Vector, Tree, Graph}},
      {"novelty", {Vector, Tree, Graph}},
      {"neat", {Graph}},
  };
  ASSERT_EQ(algorithms().size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const auto& [name, kinds] = expected[i];
    const Algorithm* a = find_algorithm(name);
    ASSERT_NE(a, nullptr) << name;
    EXPECT_EQ(a, &algorithms()[i]) << name << ": the table keeps its order";
    EXPECT_EQ(a->name, name);
    EXPECT_EQ(a->kinds, kinds) << name;
    EXPECT_FALSE(a->what.empty()) << name;
    EXPECT_EQ(a->state_format, 1U) << name;
    EXPECT_TRUE(a->defaults().has_value()) << name;
  }
  EXPECT_EQ(find_algorithm("neat_c++"), nullptr);
  EXPECT_EQ(find_algorithm(""), nullptr);
}

TEST(Registry, DefaultsOfEveryAlgorithmAreWhatItsOptionsPrintAndItsChecksAccept) {
  Problem network;
  network.genome_size = 12;
  network.objectives = {{0, 1}};
  network.descriptors = {{0, 1}, {0, 1}};
  for (const Algorithm& a : algorithms()) {
    const std::any s = a.defaults();
    for (const AlgorithmOption& o : a.options()) {
      if (o.experiments_generations) continue;   // the experiment's: no text of the algorithm's
      EXPECT_FALSE(o.text(s).empty()) << a.name << "." << o.key;
    }
    if (!a.kinds.has(Vector)) continue;
    EXPECT_GT(a.population(s, network), 0U) << a.name;
    EXPECT_GT(a.memory(s, network, 3).bytes, 0.0) << a.name;
  }
}

TEST(Registry, CvtMapElitesIsMapElitesUnderItsOwnNameOptionsAndDefaults) {
  const Algorithm& grid = *find_algorithm("map_elites");
  const Algorithm& cvt = *find_algorithm("cvt_map_elites");
  EXPECT_EQ(grid.what, "MAP-Elites");
  EXPECT_EQ(cvt.what, "CVT-MAP-Elites");
  EXPECT_EQ(grid.kinds, cvt.kinds);
  EXPECT_FALSE(std::any_cast<MapElitesRunSettings>(grid.defaults()).cvt);
  EXPECT_TRUE(std::any_cast<MapElitesRunSettings>(cvt.defaults()).cvt);
  const auto g = keys(grid), c = keys(cvt);
  EXPECT_NE(std::find(g.begin(), g.end(), "bins"), g.end());
  EXPECT_EQ(std::find(c.begin(), c.end(), "bins"), c.end());
  EXPECT_NE(std::find(c.begin(), c.end(), "cells"), c.end());
  // The same value type: its other name is a value, not a second row of functions.
  const MapElitesAlgorithm centroidal = MapElitesAlgorithm::centroidal();
  EXPECT_EQ(centroidal.name, cvt.name);
  EXPECT_EQ(&centroidal.options(), &cvt.options());
  EXPECT_EQ(&MapElitesAlgorithm{}.options(), &grid.options());
}

TEST(Registry, EveryAlgorithmListsItsOptionsThePapersWithTheirHistoricSpellings) {
  for (const Algorithm& a : algorithms()) EXPECT_FALSE(a.options().empty()) << a.name;
  const Algorithm& es = *find_algorithm("es");
  const Algorithm& gp = *find_algorithm("gp");
  // The ES's keys are bare (`--set mu=30`) and its settings in every experiment; GP's are
  // `gp.KEY`, held where the script gives them; every other's is used where it evolves.
  EXPECT_TRUE(es.bare_keys);
  EXPECT_EQ(es.scope, SettingsScope::Always);
  EXPECT_FALSE(gp.bare_keys);
  EXPECT_EQ(gp.scope, SettingsScope::Given);
  for (const char* name : {"cmaes", "nsga2", "map_elites", "cvt_map_elites", "novelty", "neat"}) {
    EXPECT_FALSE(find_algorithm(name)->bare_keys) << name;
    EXPECT_EQ(find_algorithm(name)->scope, SettingsScope::InUse) << name;
  }
  EXPECT_EQ(keys(es), (std::vector<std::string>{"mu", "lambda", "selection", "recombination", "step_sizes", "bounds",
                                                 "sigma", "min_sigma", "generations"}));
  const auto g = keys(gp);
  EXPECT_EQ(g.size(), 14U);
  EXPECT_NE(std::find(g.begin(), g.end(), "init_depth"), g.end());
  // `es(generations N)` is the experiment's generations, GP's `generations` its own.
  EXPECT_TRUE(es.options().back().experiments_generations);
  for (const AlgorithmOption& o : gp.options()) EXPECT_FALSE(o.experiments_generations) << o.key;

  // A row takes a value into the algorithm's own settings, or says why not.
  std::any s = es.defaults();
  const auto row = [](const Algorithm& a, std::string_view key) {
    const auto& rows = a.options();
    return *std::find_if(rows.begin(), rows.end(), [&](const AlgorithmOption& o) { return o.key == key; });
  };
  OptionValue v;
  v.word = 1;
  EXPECT_TRUE(row(es, "selection").set(s, v).empty());
  EXPECT_EQ(std::any_cast<const EsSettings&>(s).selection, Selection::Plus);
  EXPECT_EQ(row(es, "selection").text(s), "plus");
  v.number = 1e300;
  EXPECT_EQ(row(es, "sigma").set(s, v).message, "must be at most 1000, found 1e+300");
  v.lo = 2.0;
  v.hi = -2.0;
  const OptionRefusal empty = row(es, "bounds").set(s, v);
  EXPECT_TRUE(empty.names_option);
  EXPECT_EQ(empty.message, "empty bounds: the lower bound (2) must be below the upper (-2)");
  v.lo = 3.0;
  v.hi = 2.0;
  std::any t = gp.defaults();
  EXPECT_EQ(row(gp, "init_depth").set(t, v).message,
            "`init_depth [3, 2]` is empty: the first depth must not exceed the second");
  v.number = 1.5;
  EXPECT_EQ(row(gp, "crossover").set(t, v).message, "is a probability in [0, 1], found 1.5");

  // Options that do not go together, whatever they evolve (the ES's); GP's against a tree's set.
  EsSettings few;
  few.mu = 40;
  few.lambda = 25;
  const OptionRefusal c = es.conflict(few);
  EXPECT_EQ(c.message, "comma selection needs `lambda` >= `mu`, found mu 40 and lambda 25");
  EXPECT_EQ(c.help, "raise `lambda`, or use `plus` selection");
  EXPECT_TRUE(es.conflict(es.defaults()).empty());
  gp::GpSettings elitist;
  elitist.elitism = 1000;
  EXPECT_EQ(gp.problem(elitist, Problem{}), "elitism must be in [0, population (150)], got 1000");
  EXPECT_EQ(gp.problem(gp.defaults(), Problem{}), "");
}

// A value type of an algorithm not in the table: what a new folder defines, erased the same
// way (one value per algorithm, no row of function pointers); what it leaves out of the
// optional members is the registry's default.
struct Counting {
  struct Settings {
    int population = 3;
  };
  std::string_view name = "counting";
  std::string_view what = "a counter";
  GenomeKinds kinds{Vector};
  std::uint32_t state_format = 7;
  int* made = nullptr;

  [[nodiscard]] std::unique_ptr<Optimizer> make(const Settings& /*s*/, const Problem& /*p*/) const {
    ++*made;
    return nullptr;
  }
  [[nodiscard]] std::size_t population(const Settings& s, const Problem& p) const {
    return static_cast<std::size_t>(s.population) * p.genome_size;
  }
  [[nodiscard]] MemoryPeak memory(const Settings& /*s*/, const Problem& /*p*/, int generations) const {
    return {.bytes = static_cast<double>(generations), .candidates = 0.0, .what = "counted", .setting = {}};
  }
  // No options() nor defaults(): optional.
  [[nodiscard]] std::string problem(const Settings& s, const Problem& /*p*/) const {
    return s.population > 2 ? "" : "too few";
  }
};
static_assert(AlgorithmValue<Counting>);
static_assert(AlgorithmValue<MapElitesAlgorithm>);

TEST(Registry, ErasesAValueTypeOnceAndCallsItWithItsOwnSettings) {
  int made = 0;
  const Algorithm a(Counting{.made = &made});
  EXPECT_EQ(a.name, "counting");
  EXPECT_EQ(a.state_format, 7U);
  Problem p;
  p.genome_size = 5;
  const std::any s = a.defaults();
  EXPECT_EQ(a.population(s, p), 15U);
  EXPECT_EQ(a.memory(s, p, 9).bytes, 9.0);
  EXPECT_EQ(a.problem(s, p), "");
  EXPECT_EQ(a.problem(Counting::Settings{2}, p), "too few");
  EXPECT_TRUE(a.options().empty());
  EXPECT_EQ(std::any_cast<Counting::Settings>(a.defaults()).population, 3);
  (void)a.make(s, p);
  const Algorithm copy = a;   // copies share the one erased value
  (void)copy.make(s, p);
  EXPECT_EQ(made, 2);
  EXPECT_THROW((void)a.population(std::any(1.5), p), std::bad_any_cast) << "another algorithm's settings";
}

TEST(Registry, AProblemNamesTheKindOfItsGenome) {
  Problem p;
  p.genome_size = 4;
  EXPECT_EQ(p.kind(), Vector);
  const genome::tree::PrimitiveSet set = genome::tree::test::number_set();
  p.tree.primitives = &set;
  EXPECT_EQ(p.kind(), Tree);
}

}  // namespace
}  // namespace esc::evo
