// NSGA-II, novelty search and MAP-Elites over trees (the GP's operators on encoded trees,
// genome/tree/tree_variation.hpp), through the Optimizer interface as a run drives them, on
// objectives and descriptors of the trees' shape alone (no robot): the count of `+` nodes
// against the size, which conflict, since every `+` adds two nodes at least.
#include <gtest/gtest.h>

#include <algorithm>
#include <any>
#include <cstdio>
#include <cstring>
#include <utility>
#include <set>
#include <string>
#include <vector>

#include "runtime/genome/tree/codec.hpp"
#include "runtime/genome/tree/tree_variation.hpp"
#include "runtime/evo/map_elites/map_elites_optimizer.hpp"
#include "runtime/evo/measured_state.hpp"
#include "runtime/evo/novelty/novelty_optimizer.hpp"
#include "runtime/evo/nsga2/nsga2.hpp"
#include "runtime/evo/registry.hpp"
#include "tests/gp/helpers.hpp"

namespace esc::evo {
namespace {

struct Shapes {
  genome::tree::PrimitiveSet set = genome::tree::test::number_set();
  genome::tree::TreeOperators operators{.crossover = 0.5, .subtree_mutation = 0.2, .point_mutation = 0.2, .hoist_mutation = 0.1,
                                     .max_depth = 8, .max_size = 40, .init_max_depth = 4};

  // Objectives: `+` nodes, and the size negated (both maximised); descriptors: size and
  // depth as fractions of the limits.
  [[nodiscard]] std::vector<Outcome> measure(const std::vector<Genome>& genomes) const {
    std::vector<Outcome> out;
    for (const Genome& x : genomes) {
      const genome::tree::Tree t = genome::tree::decode(x, set);
      const auto adds = std::count_if(t.nodes.begin(), t.nodes.end(), [&](const genome::tree::Node& n) { return set[n.prim].name == "+"; });
      const double size = static_cast<double>(t.size());
      out.push_back({{static_cast<double>(adds), -size},
                     {size / operators.max_size, static_cast<double>(genome::tree::depth(t)) / operators.max_depth}});
    }
    return out;
  }

  [[nodiscard]] Problem problem(std::uint64_t seed = 5) const {
    Problem p;
    p.tree.primitives = &set;
    p.tree.operators = &operators;
    p.seed = seed;
    p.objectives = {{0, 20}, {-40, 0}};
    p.descriptors = {{0, 1}, {0, 1}};
    return p;
  }
};

struct Named {
  std::string name;
  std::any settings;
};

std::unique_ptr<Optimizer> make(std::string_view algorithm, const std::any& settings, const Problem& p) {
  return find_algorithm(algorithm)->make(settings, p);
}

std::any nsga2_settings() {
  Nsga2Settings s;
  s.population = 40;
  return s;
}

std::any novelty_settings() {
  NoveltyRunSettings s;
  s.population = 40;
  s.with_fitness = true;
  s.k = 5;
  return s;
}

std::any map_elites_settings() {
  MapElitesRunSettings s;
  s.bins = 8;
  s.batch = 20;
  s.initial = 20;
  return s;
}

std::vector<Named> all_three() {
  return {{"nsga2", nsga2_settings()}, {"novelty", novelty_settings()}, {"map_elites", map_elites_settings()}};
}

double metric(const Optimizer& o, std::string_view name) {
  for (const Metric& m : o.metrics())
    if (m.name == name) return m.value;
  ADD_FAILURE() << "no metric " << name;
  return 0.0;
}

// `generations` generations of `o` on the shapes; the metric `name` after the first and
// after the last (printed: what the docs quote).
std::pair<double, double> evolve(Optimizer& o, const Shapes& shapes, int generations, std::string_view name) {
  o.tell(shapes.measure(o.ask(0)));
  const double first = metric(o, name);
  for (int g = 1; g < generations; ++g) o.tell(shapes.measure(o.ask(g)));
  const double last = metric(o, name);
  std::printf("%s: %g after generation 1, %g after %d\n", std::string(name).c_str(), first, last, generations);
  return {first, last};
}

TEST(TreeNsga2, FindsAFrontOfTradeOffsBetweenAddsAndSize) {
  const Shapes shapes;
  auto o = make("nsga2", nsga2_settings(), shapes.problem());
  const auto [first_hv, last_hv] = evolve(*o, shapes, 25, "hypervolume");
  const Members front = *o->members(false);
  std::set<double> adds;
  for (const Member& m : front.members) {
    adds.insert(m.objectives[0]);
    // Each member is a tree of the set whose measured objectives the front keeps.
    EXPECT_EQ(shapes.measure({m.genome}).front().objectives, m.objectives);
  }
  std::printf("front: %zu trees, %zu trade-offs, up to %g `+`\n", front.members.size(), adds.size(), *adds.rbegin());
  EXPECT_GE(adds.size(), 4u) << "a front of at least four trade-offs";
  EXPECT_GT(last_hv, first_hv);
  // The smallest tree (one node, no `+`) and a tree of several `+` nodes are both kept.
  EXPECT_EQ(*adds.begin(), 0.0);
  EXPECT_GE(*adds.rbegin(), 3.0);
}

TEST(TreeNovelty, ArchivesBehaviorsAndKeepsAFrontOfNoveltyAndFitness) {
  const Shapes shapes;
  auto o = make("novelty", novelty_settings(), shapes.problem());
  const auto [first, last] = evolve(*o, shapes, 10, "archive");
  EXPECT_GT(last, first);
  const Members front = *o->members(false);
  EXPECT_EQ(front.own_objectives, std::vector<std::string>{"novelty"});
  ASSERT_FALSE(front.members.empty());
  for (const Member& m : front.members) EXPECT_NO_THROW((void)genome::tree::decode(m.genome, shapes.set));
}

TEST(TreeMapElites, FillsMoreCellsOverGenerations) {
  const Shapes shapes;
  auto o = make("map_elites", map_elites_settings(), shapes.problem());
  const auto [first, last] = evolve(*o, shapes, 30, "coverage");
  EXPECT_GT(last, first * 1.5);
  EXPECT_GT(metric(*o, "qd_score"), 0.0);
  const Members archive = *o->members(false);
  EXPECT_EQ(archive.bins, (std::vector<std::size_t>{8, 8}));
  for (const Member& m : archive.members)
    EXPECT_EQ(shapes.measure({m.genome}).front().descriptors, m.descriptors);
}

// Each child is one elite mutated: never a copy, though the GP's own probabilities (50 %
// crossover, then 20 %, 20 %, 10 % mutations) would leave none of its crossed-out share
// mutated.
TEST(TreeMapElites, EveryChildIsAMutation) {
  const Shapes shapes;
  const genome::tree::TreeVariation trees(shapes.operators, shapes.set);
  Rng rng(3);
  const std::vector<Genome> parents = trees.first(50, rng);
  int same = 0;
  for (const Genome& p : parents) same += trees.mutate_one(p, rng) == p ? 1 : 0;
  EXPECT_LT(same, 10);   // a hoist of a terminal, a point mutation without alternative
}

// Any of the three stopped after any generation, saved and loaded into a fresh one, asks
// for exactly what the one never stopped asks for.
TEST(TreeSearch, ResumesBitIdenticallyAfterAnyGeneration) {
  const Shapes shapes;
  for (const auto& [name, settings] : all_three()) {
    auto whole = make(name, settings, shapes.problem());
    std::vector<std::vector<Genome>> asked;
    for (int g = 0; g < 6; ++g) {
      asked.push_back(whole->ask(g));
      whole->tell(shapes.measure(asked.back()));
    }
    for (int stop = 0; stop < 5; stop += 2) {
      auto first = make(name, settings, shapes.problem());
      for (int g = 0; g <= stop; ++g) first->tell(shapes.measure(first->ask(g)));
      auto resumed = make(name, settings, shapes.problem());
      resumed->load(first->save());
      EXPECT_EQ(resumed->save(), first->save()) << name;
      for (int g = stop + 1; g < 6; ++g) {
        const std::vector<Genome> candidates = resumed->ask(g);
        ASSERT_EQ(candidates, asked[static_cast<std::size_t>(g)]) << name << " stopped after " << stop;
        resumed->tell(shapes.measure(candidates));
      }
    }
    // Another seed searches elsewhere.
    EXPECT_NE(make(name, settings, shapes.problem(6))->ask(0), asked.front()) << name;
  }
}

TEST(TreeSearch, NeedsTheGpSettingsAndCountsTreesInItsMemory) {
  const Shapes shapes;
  Problem p = shapes.problem();
  for (const auto& [name, settings] : all_three()) {
    const Algorithm& a = *find_algorithm(name);
    EXPECT_EQ(a.problem(settings, p), "") << name;
    const double small = a.memory(settings, p, 6).bytes;
    genome::tree::TreeOperators bigger = shapes.operators;
    bigger.max_size = 400;
    Problem q = p;
    q.tree.operators = &bigger;
    EXPECT_GT(a.memory(settings, q, 6).bytes, 3.0 * small) << name << ": a tree counts max_size nodes";
    q.tree.operators = nullptr;
    EXPECT_NE(a.problem(settings, q).find("`evolve gp(...)`"), std::string::npos) << name;
    EXPECT_THROW((void)a.make(settings, q), std::invalid_argument) << name;
  }
  genome::tree::TreeOperators still = shapes.operators;
  still.subtree_mutation = still.point_mutation = still.hoist_mutation = 0.0;
  p.tree.operators = &still;
  EXPECT_NE(find_algorithm("map_elites")->problem(map_elites_settings(), p).find("are all 0"), std::string::npos);
}

// Every member of a front or an archive knows the evaluation that measured it (the
// generation and its index among that generation's candidates: what a replay derives its
// evaluation's seed from), across a save and load; a state saved before origins were kept
// (the core's bytes alone; novelty search's version 1) loads with them unknown.
TEST(TreeSearch, EveryMemberKnowsTheEvaluationThatMeasuredIt) {
  const Shapes shapes;
  for (const Named& a : all_three()) {
    SCOPED_TRACE(a.name);
    auto o = make(a.name, a.settings, shapes.problem());
    std::vector<std::vector<Genome>> asked;
    for (int g = 0; g < 8; ++g) {
      asked.push_back(o->ask(g));
      o->tell(shapes.measure(asked.back()));
    }
    const Members kept = *o->members(false);
    ASSERT_FALSE(kept.members.empty());
    std::set<std::int64_t> generations;
    for (const Member& m : kept.members) {
      ASSERT_TRUE(m.measured.known());
      const auto g = static_cast<std::size_t>(m.measured.generation);
      ASSERT_LT(g, asked.size());
      ASSERT_LT(m.measured.candidate, asked[g].size());
      EXPECT_EQ(asked[g][m.measured.candidate], m.genome);
      generations.insert(m.measured.generation);
    }
    EXPECT_GT(generations.size(), 1u) << "members of several generations";

    const StateBytes state = o->save();
    auto again = make(a.name, a.settings, shapes.problem());
    again->load(state);
    EXPECT_EQ(again->members(false)->members, kept.members);

    // The state an esc before wrote: origins unknown, everything else as it was.
    StateBytes older;
    if (a.name == "novelty") {
      const std::size_t trailer = sizeof(std::uint64_t) + 40 * 2 * sizeof(std::uint64_t);   // 40 parents
      older.assign(state.begin(), state.end() - static_cast<std::ptrdiff_t>(trailer));
      const std::uint32_t one = 1;
      std::memcpy(older.data() + sizeof(std::uint64_t) + std::string_view("esc-novelty").size(), &one, sizeof one);
    } else {
      older = read_with_measured(a.name == "nsga2" ? "esc-nsga2-run" : "esc-map-elites-run", state).core;
    }
    auto old = make(a.name, a.settings, shapes.problem());
    old->load(older);
    const Members was = *old->members(false);
    ASSERT_EQ(was.members.size(), kept.members.size());
    for (std::size_t i = 0; i < was.members.size(); ++i) {
      EXPECT_FALSE(was.members[i].measured.known());
      EXPECT_EQ(was.members[i].genome, kept.members[i].genome);
    }
    // It carries on, and what it measures from then on is known.
    old->tell(shapes.measure(old->ask(8)));
    std::size_t known = 0;
    const Members now = *old->members(false);
    for (const Member& m : now.members)
      if (m.measured.known()) {
        EXPECT_EQ(m.measured.generation, 8);
        ++known;
      }
    EXPECT_GT(known, 0u);
  }
}

}  // namespace
}  // namespace esc::evo
