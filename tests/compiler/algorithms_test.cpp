// Which algorithm evolves which controller: `evolve NAME(...)`, `compare C by NAME`,
// `--set networks=NAME` and `--set NAME.KEY` (CMA-ES here, as the first algorithm beyond the
// paper's ES and GP); the errors are in tests/bad/.
#include <gtest/gtest.h>

#include "compiler/algorithm_options.hpp"
#include "helpers.hpp"
#include "runtime/evo/cmaes/cmaes.hpp"
#include "tests/algorithm_settings.hpp"

namespace esc::compiler {
namespace {

using test::options;
using test::paper;
using test::rendered;

constexpr const char* kHead =
    "arena a { size 1m x 1m }\n"
    "fitness f { step: speed }\n"
    "controller c = mlp(ir[0..7] -> wheels)\n"
    "controller d = symbolic(mlp(ir[0..7]), actions [forward, left, right])\n"
    "import \"lib/khepera.esc\"\n";

eval::ExperimentSpec compiled(const std::string& experiment) {
  const CompileResult r = compile_source(std::string(kHead) + experiment, "algorithms.esc", options());
  EXPECT_TRUE(r.ok()) << rendered(r);
  return r.ok() ? r.experiments.at(0) : eval::ExperimentSpec{};
}

std::string algorithm_of(const eval::ExperimentSpec& x, std::size_t i) {
  return std::string(x.evolution_of(x.controllers.at(i)).algorithm->name);
}

const evo::CmaesSettings& cmaes(const eval::ExperimentSpec& x) {
  return std::any_cast<const evo::CmaesSettings&>(x.algorithm_settings.at("cmaes"));
}

TEST(Algorithms, EvolveCmaesAloneEvolvesTheNetworksWithItsOptions) {
  const auto x = compiled("experiment e { arena a  fitness f  evolve cmaes(lambda 20, mu 5, sigma 0.3, separable, "
                          "restarts 2) for 40 generations  compare c, d }");
  EXPECT_EQ(algorithm_of(x, 0), "cmaes");
  EXPECT_EQ(algorithm_of(x, 1), "cmaes");
  EXPECT_EQ(cmaes(x).lambda, 20);
  EXPECT_EQ(cmaes(x).mu, 5);
  EXPECT_DOUBLE_EQ(cmaes(x).sigma, 0.3);
  EXPECT_TRUE(cmaes(x).separable);
  EXPECT_EQ(cmaes(x).restarts, 2);
  EXPECT_EQ(x.generations, 40);   // the experiment's generations
  EXPECT_EQ(x.evaluations_per_generation(x.controllers[0]), 20u);
  EXPECT_EQ(x.resolved_settings.at("networks"), "cmaes");
  EXPECT_EQ(x.resolved_settings.at("cmaes.covariance"), "separable");
  EXPECT_EQ(x.resolved_settings.at("cmaes.lambda"), "20");
}

TEST(Algorithms, ByChoosesForOneControllerBesideTheDefault) {
  const auto x = compiled("experiment e { arena a  fitness f  evolve es(mu 3, lambda 12)  "
                          "compare c, c by cmaes as c_cma, d }");
  EXPECT_EQ(algorithm_of(x, 0), "es");
  EXPECT_EQ(algorithm_of(x, 1), "cmaes");
  EXPECT_EQ(algorithm_of(x, 2), "es");
  EXPECT_EQ(x.controllers[1].name, "c_cma");
  EXPECT_EQ(cmaes(x).lambda, 0);   // its defaults: no `evolve cmaes`
  // CMA-ES's default population for c's 18 weights: 4 + floor(3 ln 18) = 12.
  EXPECT_EQ(x.evaluations_per_generation(x.controllers[1]), 12u);
  EXPECT_EQ(x.resolved_settings.count("networks"), 0u);
  EXPECT_EQ(x.resolved_settings.at("cmaes.lambda"), "0");
  // `by` is part of what was compared (the resolved settings, so resume and the dependency
  // cache tell the two scripts apart) and travels with the controller (`--controllers c_cma`).
  EXPECT_EQ(x.resolved_settings.at("compare"), "c, c_cma by cmaes, d");
  eval::ExperimentSpec alone = x;
  alone.controllers = {x.controllers[1]};
  EXPECT_EQ(algorithm_of(alone, 0), "cmaes");
}

TEST(Algorithms, TheExperimentsGenerationsAreGivenOnce) {
  const CompileResult r = compile_source(
      std::string(kHead) + "experiment e { arena a  fitness f  evolve es(mu 3, lambda 12) for 20 generations\n"
                           "  evolve cmaes(lambda 12) for 30 generations  compare c, c by cmaes as c_cma }",
      "generations.esc", options());
  ASSERT_FALSE(r.ok());
  EXPECT_NE(rendered(r).find("generations.esc:7:31: error: the experiment's number of generations is already given"),
            std::string::npos)
      << rendered(r);
}

// The paper's scripts name no new algorithm: nothing of one appears in their settings, so
// their runs and dependency caches keep their fingerprints.
TEST(Algorithms, ThePaperScriptsResolveAsBefore) {
  const eval::ExperimentSpec x = paper();
  ASSERT_EQ(x.algorithm_settings.size(), 1U);   // the ES's, which every experiment holds
  EXPECT_EQ(x.algorithm_settings.count("es"), 1U);
  for (const auto& [key, value] : x.resolved_settings) {
    EXPECT_FALSE(key.starts_with("cmaes.")) << key;
    EXPECT_NE(key, "networks");
  }
  for (const auto& c : x.controllers) EXPECT_EQ(x.evolution_of(c).algorithm->name, "es");
}

TEST(Algorithms, SetNetworksAndCmaesKeys) {
  eval::ExperimentSpec x = paper();
  EXPECT_EQ(apply_settings(x, {{"cmaes.lambda", "30"}, {"networks", "cmaes"}, {"cmaes.covariance", "separable"}}), "");
  EXPECT_EQ(x.networks, "cmaes");
  EXPECT_EQ(cmaes(x).lambda, 30);   // given before `networks`, kept
  EXPECT_TRUE(cmaes(x).separable);
  EXPECT_EQ(x.resolved_settings.at("networks"), "cmaes");
  EXPECT_EQ(x.resolved_settings.at("cmaes.lambda"), "30");
  EXPECT_EQ(apply_setting(x, "networks", "es"), "");
  EXPECT_EQ(x.resolved_settings.count("networks"), 0u);
  EXPECT_EQ(x.resolved_settings.count("cmaes.lambda"), 0u);   // CMA-ES evolves nothing now

  eval::ExperimentSpec y = paper();
  const auto before = y.resolved_settings;
  std::string m = apply_setting(y, "cmaes.lamda", "30");
  EXPECT_NE(m.find("unknown CMA-ES setting `cmaes.lamda`; did you mean `cmaes.lambda`?"), std::string::npos) << m;
  m = apply_setting(y, "networks", "gp");
  EXPECT_NE(m.find("networks"), std::string::npos) << m;
  m = apply_settings(y, {{"networks", "cmaes"}, {"cmaes.lambda", "10"}, {"cmaes.mu", "9"}});
  EXPECT_NE(m.find("impossible CMA-ES settings"), std::string::npos) << m;
  EXPECT_EQ(y.resolved_settings, before);
  EXPECT_EQ(y.networks, "es");
}

// The paper's ES and GP are read like every algorithm, from their folders' tables, into
// algorithm_settings; their historic spellings hold (`mu`, `es(generations N)`, `gp.KEY`), and
// the experiment's generations are its own, GP's the trees'.
TEST(Algorithms, TheEsAndGpAreOrdinaryEntriesWithTheirHistoricSpellings) {
  eval::ExperimentSpec x = compiled(
      "primitives p { functions + - if <  terminals ir[0..7], erc(-1, 1) }\n"
      "controller t = tree(wheels, primitives p)\n"
      "experiment e { arena a  fitness f  evolve es(mu 4, lambda 9, plus, generations 7)\n"
      "  evolve gp(population 11, init_depth [2, 3]) for 5 generations  compare c, t }");
  ASSERT_EQ(x.algorithm_settings.size(), 2U);
  EXPECT_EQ(es_of(x).mu, 4);
  EXPECT_EQ(es_of(x).selection, evo::Selection::Plus);
  EXPECT_EQ(gp_of(x).population, 11);
  EXPECT_EQ(gp_of(x).init_max_depth, 3);
  EXPECT_EQ(x.generations, 7);   // `es(generations 7)`: the experiment's
  EXPECT_EQ(gp_of(x).generations, 5);
  EXPECT_EQ(x.generations_for(x.controllers[0]), 7);
  EXPECT_EQ(x.generations_for(x.controllers[1]), 5);
  EXPECT_EQ(x.evolution_of(x.controllers[0]).algorithm->name, "es");
  EXPECT_EQ(x.evolution_of(x.controllers[1]).algorithm->name, "gp");
  EXPECT_EQ(x.evaluations_per_generation(x.controllers[0]), 9U);
  EXPECT_EQ(x.evaluations_per_generation(x.controllers[1]), 11U);
  EXPECT_EQ(x.resolved_settings.at("mu"), "4");
  EXPECT_EQ(x.resolved_settings.at("selection"), "plus");
  EXPECT_EQ(x.resolved_settings.at("generations"), "7");
  EXPECT_EQ(x.resolved_settings.at("gp.generations"), "5");
  EXPECT_EQ(x.resolved_settings.at("gp.init_depth"), "[2, 3]");
  EXPECT_EQ(x.resolved_settings.count("es.mu"), 0U);

  // `--set generations` is the experiment's and GP's; `--set mu` the ES's, bare.
  EXPECT_EQ(apply_settings(x, {{"generations", "3"}, {"mu", "2"}, {"gp.tournament", "4"}}), "");
  EXPECT_EQ(x.generations, 3);
  EXPECT_EQ(gp_of(x).generations, 3);
  EXPECT_EQ(es_of(x).mu, 2);
  EXPECT_EQ(gp_of(x).tournament, 4);
  EXPECT_EQ(x.resolved_settings.at("gp.tournament"), "4");
  std::string m = apply_setting(x, "es.mu", "3");
  EXPECT_NE(m.find("unknown setting `es.mu`"), std::string::npos) << m;
  m = apply_setting(x, "mu", "0");
  EXPECT_NE(m.find("`mu` must be at least 1, found 0"), std::string::npos) << m;
  m = apply_setting(x, "gp.init_depth", "[3, 2]");
  EXPECT_NE(m.find("`init_depth [3, 2]` is empty"), std::string::npos) << m;

  // An experiment without `evolve gp` holds no GP settings: `--set gp.KEY` is checked and dropped.
  eval::ExperimentSpec y = compiled("experiment e { arena a  fitness f  compare c }");
  EXPECT_EQ(apply_setting(y, "gp.population", "20"), "");
  EXPECT_EQ(y.tree_operators(), nullptr);
  EXPECT_EQ(y.resolved_settings.count("gp.population"), 0U);
  m = apply_setting(y, "gp.population", "0");
  EXPECT_NE(m.find("`population` must be at least 1, found 0"), std::string::npos) << m;
}

TEST(Algorithms, EveryAlgorithmIsRegisteredAndHasItsKeys) {
  ASSERT_EQ(algorithm_options().size(), evo::algorithms().size());
  for (const AlgorithmOptions& a : algorithm_options()) {
    const evo::Algorithm* r = evo::find_algorithm(a.name);
    ASSERT_NE(r, nullptr) << a.name;
    EXPECT_FALSE(a.keys().empty());
    for (const std::string& k : a.keys()) EXPECT_TRUE(a.has_key(k)) << a.name << "." << k;
    std::map<std::string, std::string> resolved;
    a.resolve(a.defaults(), resolved);
    EXPECT_EQ(resolved.size(), a.keys().size());
    // Every key but the ES's, the paper's, spells its algorithm: `gp.population`, `cmaes.sigma`.
    for (const auto& [key, text] : resolved) EXPECT_TRUE(key.starts_with(a.group)) << key;
    EXPECT_EQ(a.group.empty(), a.name == "es") << a.name;
    a.unresolve(resolved);
    EXPECT_TRUE(resolved.empty()) << a.name;
  }
}

}  // namespace
}  // namespace esc::compiler
