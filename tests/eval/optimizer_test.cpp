// The optimizer interface as the run loop uses it, for every registered algorithm: a state
// saved after any generation and loaded into a fresh optimizer continues exactly as the one
// never stopped; a state it could not have saved is refused; the registry names each
// algorithm once with what it evolves.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "runtime/eval/experiment.hpp"
#include "runtime/eval/run_optimizer.hpp"
#include "runtime/evo/evaluate_only.hpp"
#include "runtime/genome/tree/codec.hpp"
#include "runtime/evo/registry.hpp"
#include "tests/eval/gp_experiment.hpp"
#include "tests/algorithm_settings.hpp"

namespace esc::eval {
namespace {

// A fitness that depends on every gene of the candidate, a second objective and two
// descriptors, for ask/tell without a robot.
std::vector<evo::Outcome> measure(const std::vector<evo::Genome>& candidates) {
  std::vector<evo::Outcome> out;
  for (const evo::Genome& g : candidates) {
    double f = 0.0;
    for (std::size_t i = 0; i < g.size(); ++i) f += std::sin(static_cast<double>(i) + g[i]);
    out.push_back({{f, -std::abs(g.front())}, {(std::sin(g.front()) + 1) / 2, (std::cos(g.back()) + 1) / 2}});
  }
  return out;
}

// Two objectives and two descriptors, declared with their ranges, as every algorithm may
// need them (NSGA-II's hypervolume, MAP-Elites' cells).
void declare_objectives(ExperimentSpec& x) {
  x.objectives = {{"f", false, DeclaredRange{-100, 100}}, {"g", true, DeclaredRange{0, 1}}};
  x.further = {x.fitness};
  x.further.front().name = "g";
  x.descriptors = {{"a", {}, {}, false, Reduction::Mean, {0, 1}}, {"b", {}, {}, false, Reduction::Mean, {0, 1}}};
}

struct Case {
  std::string name;        // the algorithm's, and " (trees)" for one that evolves both
  std::string algorithm;
  ExperimentSpec spec;
  std::size_t controller;
};

// Every registered algorithm on each kind of controller it evolves: a network of the small
// experiment, the GP experiment's Action tree, the small experiment's network as NEAT's.
std::vector<Case> cases() {
  std::vector<Case> v;
  for (const evo::Algorithm& a : evo::algorithms()) {
    const std::string name(a.name);
    if (a.kinds.has(genome::GenomeKind::Tree)) {
      ExperimentSpec x = testing::gp_experiment();
      declare_objectives(x);
      x.controllers[1].evolved_by = name;
      x.algorithm_settings.try_emplace(name, a.defaults());   // GP's: the experiment's own
      v.push_back({a.kinds.has(genome::GenomeKind::Vector) ? name + " (trees)" : name, name, std::move(x), 1});
    }
    if (a.kinds.has(genome::GenomeKind::Graph)) {   // the small experiment's CC as a NEAT network
      ExperimentSpec x = testing::small_experiment();
      declare_objectives(x);
      x.controllers[0].mlp.kind = control::NetworkKind::Graph;
      x.controllers[0].mlp.hidden.clear();
      x.controllers[0].evolved_by = name;
      x.algorithm_settings[name] = a.defaults();
      v.push_back({a.kinds.has(genome::GenomeKind::Vector) ? name + " (graphs)" : name, name, std::move(x), 0});
    }
    if (!a.kinds.has(genome::GenomeKind::Vector)) continue;
    ExperimentSpec x = testing::small_experiment();
    declare_objectives(x);
    x.networks = name;
    x.algorithm_settings.try_emplace(x.networks, a.defaults());   // the ES's: the experiment's own
    v.push_back({name, name, std::move(x), 0});
  }
  return v;
}

std::unique_ptr<evo::Optimizer> make(const ExperimentSpec& spec, const control::ControllerSpec& c,
                                     const evo::Genome* start = nullptr) {
  const Evolution e = spec.evolution_of(c);
  evo::Problem p = spec.problem_of(c);
  p.seed = 77;
  p.start = start;
  return e.algorithm->make(e.settings, p);
}

TEST(Optimizer, EveryAlgorithmLoadedAfterAnyGenerationContinuesAsTheUnstoppedOne) {
  for (const Case& k : cases()) {
    const control::ControllerSpec& c = k.spec.controllers[k.controller];
    ASSERT_EQ(k.spec.evolution_of(c).algorithm->name, k.algorithm);
    auto whole = make(k.spec, c);
    std::vector<std::vector<evo::Genome>> asked;
    for (int g = 0; g < 4; ++g) {
      asked.push_back(whole->ask(g));
      whole->tell(measure(asked.back()));
    }
    for (int stop = 0; stop < 3; ++stop) {
      auto first = make(k.spec, c);
      for (int g = 0; g <= stop; ++g) first->tell(measure(first->ask(g)));
      auto resumed = make(k.spec, c);
      resumed->load(first->save());
      EXPECT_EQ(resumed->save(), first->save()) << k.name;
      for (int g = stop + 1; g < 4; ++g) {
        const std::vector<evo::Genome> candidates = resumed->ask(g);
        EXPECT_EQ(candidates, asked[static_cast<std::size_t>(g)]) << k.name << " stopped after " << stop;
        resumed->tell(measure(candidates));
      }
    }
  }
}

TEST(Optimizer, AStateItCouldNotHaveSavedIsRefused) {
  for (const Case& k : cases()) {
    const control::ControllerSpec& c = k.spec.controllers[k.controller];
    auto o = make(k.spec, c);
    o->tell(measure(o->ask(0)));
    const evo::StateBytes good = o->save();
    evo::StateBytes shorter(good.begin(), good.end() - 3);
    EXPECT_THROW(make(k.spec, c)->load(shorter), std::invalid_argument) << k.name << ": truncated";
    evo::StateBytes longer = good;
    longer.push_back(0);
    EXPECT_THROW(make(k.spec, c)->load(longer), std::invalid_argument) << k.name << ": bytes after its end";
    evo::StateBytes huge = good;
    huge[0] = 0xff;   // a count of individuals beyond the bytes
    EXPECT_THROW(make(k.spec, c)->load(huge), std::invalid_argument) << k.name << ": count";
  }
  // The ES's state of another network size, or of another mu.
  ExperimentSpec spec = testing::small_experiment();
  auto es = make(spec, spec.controllers[0]);
  const evo::StateBytes state = es->save();
  ExperimentSpec more = spec;
  es_of(more).mu += 1;
  es_of(more).lambda += 5;
  EXPECT_THROW(make(more, more.controllers[0])->load(state), std::invalid_argument);
  const std::size_t n = spec.controllers[0].genome_size();
  const std::any& settings = spec.algorithm_settings.at("es");
  EXPECT_THROW(evo::find_algorithm("es")->make(settings, {n + 1, {}, 77, nullptr, {}, {}, {}})->load(state),
               std::invalid_argument);
}

// A state of one representation loaded by the same algorithm over the other is refused by
// name, not misread: a tree is never read as weights, nor weights as a tree.
TEST(Optimizer, AStateOfTheOtherRepresentationIsRefusedByName) {
  const std::vector<Case> all = cases();
  for (const Case& trees : all) {
    if (trees.name.find("(trees)") == std::string::npos) continue;
    const auto network = std::find_if(all.begin(), all.end(), [&](const Case& k) { return k.name == trees.algorithm; });
    ASSERT_NE(network, all.end());
    auto t = make(trees.spec, trees.spec.controllers[trees.controller]);
    t->tell(measure(t->ask(0)));
    auto n = make(network->spec, network->spec.controllers[network->controller]);
    n->tell(measure(n->ask(0)));
    try {
      make(network->spec, network->spec.controllers[network->controller])->load(t->save());
      ADD_FAILURE() << trees.name << ": a tree state loaded over a network";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("over trees (this one evolves a network's weights)"), std::string::npos)
          << e.what();
    }
    try {
      make(trees.spec, trees.spec.controllers[trees.controller])->load(n->save());
      ADD_FAILURE() << trees.name << ": a network state loaded over trees";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("over a network's weights (this one evolves trees)"), std::string::npos)
          << e.what();
    }
  }
}

// What a tree controller's NSGA-II, novelty search and MAP-Elites ask for are trees of its
// primitive set within the GP's limits, and what they keep (members) are such trees too.
TEST(Optimizer, TreeCandidatesAndMembersAreTreesWithinTheGpLimits) {
  for (const Case& k : cases()) {
    if (k.name.find("(trees)") == std::string::npos) continue;
    const control::ControllerSpec& c = k.spec.controllers[k.controller];
    auto o = make(k.spec, c);
    for (int g = 0; g < 3; ++g) {
      const std::vector<evo::Genome> asked = o->ask(g);
      for (const evo::Genome& x : asked) {
        const genome::tree::Tree t = genome::tree::decode(x, *c.primitives);
        EXPECT_LE(static_cast<int>(t.size()), gp_of(k.spec).max_size) << k.name;
        EXPECT_LE(genome::tree::depth(t), gp_of(k.spec).max_depth) << k.name;
      }
      o->tell(measure(asked));
    }
    const auto members = o->members(false);
    ASSERT_TRUE(members.has_value()) << k.name;
    for (const evo::Member& m : members->members) {
      if (!m.genome.empty()) {
        EXPECT_NO_THROW((void)genome::tree::decode(m.genome, *c.primitives)) << k.name;
      }
    }
  }
}

TEST(Optimizer, AStartGenomeIsCandidateZeroOfGenerationZero) {
  for (const Case& k : cases()) {
    const control::ControllerSpec& c = k.spec.controllers[k.controller];
    const evo::Genome start = make(k.spec, c)->ask(0).back();
    auto o = make(k.spec, c, &start);
    const std::vector<evo::Genome> first = o->ask(0);
    EXPECT_EQ(first.front(), start) << k.name;
    EXPECT_GT(first.size(), 1u) << k.name;
  }
}

TEST(Optimizer, EvaluatingAStoredGenomeAsksForItAloneAndKeepsNoState) {
  const evo::Genome g{0.25, -0.5};
  auto o = evo::make_evaluate_only({2, {}, 1, &g, {}, {}, {}});
  EXPECT_EQ(o->ask(0), std::vector<evo::Genome>{g});
  o->tell(measure({g}));
  EXPECT_TRUE(o->save().empty());
  EXPECT_THROW(o->load(evo::StateBytes{1}), std::invalid_argument);
  EXPECT_THROW((void)evo::make_evaluate_only({2, {}, 1, nullptr, {}, {}, {}}), std::invalid_argument);
}

TEST(Registry, NamesEachAlgorithmOnceWithWhatItEvolves) {
  const auto& all = evo::algorithms();
  for (std::size_t i = 0; i < all.size(); ++i) {
    EXPECT_EQ(evo::find_algorithm(all[i].name), &all[i]);
    EXPECT_NE(all[i].kinds, genome::GenomeKinds{}) << all[i].name;
    EXPECT_NE(all[i].name, evo::kEvaluateOnly);
  }
  ASSERT_NE(evo::find_algorithm("es"), nullptr);
  using enum genome::GenomeKind;
  EXPECT_EQ(evo::find_algorithm("es")->kinds, genome::GenomeKinds{Vector});
  EXPECT_EQ(evo::find_algorithm("cmaes")->kinds, genome::GenomeKinds{Vector});
  ASSERT_NE(evo::find_algorithm("gp"), nullptr);
  EXPECT_EQ(evo::find_algorithm("gp")->kinds, genome::GenomeKinds{Tree});
  for (const char* all_three : {"nsga2", "novelty", "map_elites", "cvt_map_elites"})
    EXPECT_EQ(evo::find_algorithm(all_three)->kinds, (genome::GenomeKinds{Vector, Tree, Graph})) << all_three;
  ASSERT_NE(evo::find_algorithm("neat"), nullptr);
  EXPECT_EQ(evo::find_algorithm("neat")->kinds, genome::GenomeKinds{Graph});
  EXPECT_EQ(evo::find_algorithm("nsga3"), nullptr);
}

// A NEAT network named for an algorithm that does not evolve graphs (a spec the compiler
// would have refused) is refused when its run's optimizer is made, never run as weights.
TEST(Registry, AnAlgorithmWithoutGraphsRefusesANeatNetwork) {
  for (const evo::Algorithm& a : evo::algorithms()) {
    if (a.kinds.has(genome::GenomeKind::Graph)) continue;
    ExperimentSpec x = testing::small_experiment();
    x.controllers[0].mlp.kind = control::NetworkKind::Graph;
    x.controllers[0].mlp.hidden.clear();
    x.controllers[0].evolved_by = std::string(a.name);
    x.algorithm_settings.try_emplace(std::string(a.name), a.defaults());
    const control::ControllerSpec& c = x.controllers[0];
    try {
      (void)make_run_optimizer(x, c, x.problem_of(c));
      ADD_FAILURE() << a.name << " made an optimizer for a NEAT network";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("does not evolve graph genomes"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace esc::eval
