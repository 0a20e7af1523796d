// The optimizer interface as the run loop uses it, for every registered algorithm: a state
// saved after any generation and loaded into a fresh optimizer continues exactly as the one
// never stopped; a state it could not have saved is refused; the registry names each
// algorithm once with what it evolves.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "runtime/eval/experiment.hpp"
#include "runtime/evo/evaluate_only.hpp"
#include "runtime/evo/registry.hpp"
#include "tests/eval/gp_experiment.hpp"

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
  x.descriptors = {{"a", {}, false, Reduction::Mean, {0, 1}}, {"b", {}, false, Reduction::Mean, {0, 1}}};
}

struct Case {
  std::string name;
  ExperimentSpec spec;
  std::size_t controller;
};

// Every registered algorithm on a controller it evolves: a network of the small experiment,
// or the GP experiment's Action tree.
std::vector<Case> cases() {
  std::vector<Case> v;
  for (const evo::Algorithm& a : evo::algorithms()) {
    if (a.trees) {
      ExperimentSpec x = testing::gp_experiment();
      declare_objectives(x);
      v.push_back({std::string(a.name), std::move(x), 1});
      continue;
    }
    ExperimentSpec x = testing::small_experiment();
    declare_objectives(x);
    x.networks = std::string(a.name);
    if (a.defaults != nullptr) x.algorithm_settings[x.networks] = a.defaults();
    v.push_back({std::string(a.name), std::move(x), 0});
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
    ASSERT_EQ(k.spec.evolution_of(c).algorithm->name, k.name);
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
  more.es.mu += 1;
  more.es.lambda += 5;
  EXPECT_THROW(make(more, more.controllers[0])->load(state), std::invalid_argument);
  const std::size_t n = spec.controllers[0].genome_size();
  EXPECT_THROW(evo::find_algorithm("es")->make(spec.es, {n + 1, nullptr, 77, nullptr, {}, {}})->load(state),
               std::invalid_argument);
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
  auto o = evo::make_evaluate_only({2, nullptr, 1, &g, {}, {}});
  EXPECT_EQ(o->ask(0), std::vector<evo::Genome>{g});
  o->tell(measure({g}));
  EXPECT_TRUE(o->save().empty());
  EXPECT_THROW(o->load(evo::StateBytes{1}), std::invalid_argument);
  EXPECT_THROW((void)evo::make_evaluate_only({2, nullptr, 1, nullptr, {}, {}}), std::invalid_argument);
}

TEST(Registry, NamesEachAlgorithmOnceWithWhatItEvolves) {
  const auto& all = evo::algorithms();
  for (std::size_t i = 0; i < all.size(); ++i) {
    EXPECT_EQ(evo::find_algorithm(all[i].name), &all[i]);
    EXPECT_TRUE(all[i].networks || all[i].trees) << all[i].name;
    EXPECT_NE(all[i].name, evo::kEvaluateOnly);
  }
  ASSERT_NE(evo::find_algorithm("es"), nullptr);
  EXPECT_TRUE(evo::find_algorithm("es")->networks);
  EXPECT_FALSE(evo::find_algorithm("es")->trees);
  ASSERT_NE(evo::find_algorithm("gp"), nullptr);
  EXPECT_TRUE(evo::find_algorithm("gp")->trees);
  EXPECT_EQ(evo::find_algorithm("nsga3"), nullptr);
}

}  // namespace
}  // namespace esc::eval
