// Genetic programming in scripts: `primitives` declarations, `tree(...)` controllers for
// the three uses, `evolve gp(...)` beside `evolve es(...)`, `--set gp.KEY=VALUE`, and the
// diagnostics that need more than one line of tests/bad to show.
#include <gtest/gtest.h>

#include <algorithm>
#include <variant>

#include "helpers.hpp"
#include "runtime/genome/tree/primitive_set.hpp"
#include "tests/algorithm_settings.hpp"

namespace esc::compiler {
namespace {

using test::options;
using test::rendered;
namespace gp = evo::gp;

const std::string kScript = R"(
import "lib/khepera.esc"
arena a { size 50cm x 50cm  cylinder at (25cm, 25cm) radius 3cm }
fitness f { step: max(forward_speed, 0)  stop epoch when collision }
behavior stop_here() { wheels(0, 0) }
behavior turn(l, r) { wheels(l, r) }
behavior go(p) { wheels(p, p) }
primitives p {
  functions + - * / min max abs < > and, or not if
  terminals ir[0..7], speed, erc(-1, 1), 0.5, 10cm, true
}
controller CC = mlp(ir[0..7] -> hidden 3 -> wheels)
controller GW = tree(wheels, primitives p)
controller GS = tree(actions [forward, turn, stop_here], primitives p)
controller GV = tree(behaviors [stop_here, turn(0.5, -0.5), go(0.8)], primitives p)
experiment e {
  arena a
  fitness f
  epochs 2 x 30 steps
  evolve es(mu 3, lambda 6) for 4 generations
  evolve gp(population 12, tournament 3, elitism 2, crossover 0.7, subtree_mutation 0.1,
            init_depth [2, 4], max_depth 9, max_size 60, erc_sigma 0.2) for 5 generations
  compare CC, GW, GS, GV
}
)";

const genome::tree::Primitive* find(const genome::tree::PrimitiveSet& set, std::string_view name, genome::tree::Kind kind) {
  for (const genome::tree::Primitive& p : set.primitives())
    if (p.name == name && p.kind == kind) return &p;
  return nullptr;
}

std::size_t count(const genome::tree::PrimitiveSet& set, genome::tree::Kind kind) {
  const auto all = set.primitives();
  return static_cast<std::size_t>(std::count_if(all.begin(), all.end(), [&](const auto& p) { return p.kind == kind; }));
}

TEST(GpSyntax, TreeControllersForTheThreeUses) {
  const CompileResult r = compile_source(kScript, "gp.esc", options());
  ASSERT_TRUE(r.ok()) << rendered(r);
  const eval::ExperimentSpec& x = r.experiments.at(0);
  ASSERT_EQ(x.controllers.size(), 4u);
  EXPECT_FALSE(x.controllers[0].is_tree());

  const control::ControllerSpec& gw = x.controllers[1];
  ASSERT_TRUE(gw.is_tree());
  EXPECT_EQ(gw.head, control::Head::Classical);
  EXPECT_EQ(gw.primitives->root(), genome::tree::Type::Wheels);
  EXPECT_EQ(gw.primitives_name, "p");
  EXPECT_EQ(gw.architecture(), "tree wheels");
  EXPECT_EQ(gw.genome_size(), 0u);
  EXPECT_EQ(x.genome_size_of(gw), 60u);   // max_size
  // 14 functions with `if` over Numbers, `if` over Wheels, 8 + 1 observables, one ERC, three
  // constants, wheels.
  EXPECT_EQ(count(*gw.primitives, genome::tree::Kind::Function), 14u);
  EXPECT_EQ(count(*gw.primitives, genome::tree::Kind::Observable), 9u);
  EXPECT_EQ(count(*gw.primitives, genome::tree::Kind::Erc), 1u);
  EXPECT_EQ(count(*gw.primitives, genome::tree::Kind::Constant), 3u);
  EXPECT_EQ(count(*gw.primitives, genome::tree::Kind::Wheels), 1u);
  ASSERT_NE(find(*gw.primitives, "ir[7]", genome::tree::Kind::Observable), nullptr);
  ASSERT_NE(find(*gw.primitives, "0.1", genome::tree::Kind::Constant), nullptr);   // 10cm in SI
  ASSERT_NE(find(*gw.primitives, "true", genome::tree::Kind::Constant), nullptr);
  const genome::tree::Primitive* erc = find(*gw.primitives, "erc", genome::tree::Kind::Erc);
  ASSERT_NE(erc, nullptr);
  EXPECT_EQ(erc->lo, -1.0);
  EXPECT_EQ(erc->hi, 1.0);

  // Actions take as many Number arguments as their behaviors have parameters.
  const control::ControllerSpec& gs = x.controllers[2];
  EXPECT_EQ(gs.head, control::Head::Symbolic);
  EXPECT_EQ(gs.primitives->root(), genome::tree::Type::Action);
  EXPECT_EQ(gs.architecture(), "tree actions");
  ASSERT_EQ(gs.actions.size(), 3u);
  EXPECT_EQ(find(*gs.primitives, "forward", genome::tree::Kind::Action)->arity, 1);
  EXPECT_EQ(find(*gs.primitives, "turn", genome::tree::Kind::Action)->arity, 2);
  EXPECT_EQ(find(*gs.primitives, "stop_here", genome::tree::Kind::Action)->arity, 0);
  EXPECT_EQ(find(*gs.primitives, "turn", genome::tree::Kind::Action)->index, 1u);
  EXPECT_EQ(gs.choice_names(), (std::vector<std::string>{"forward", "turn", "stop_here"}));

  // Supervised behaviors with their constant arguments.
  const control::ControllerSpec& gv = x.controllers[3];
  EXPECT_EQ(gv.head, control::Head::Supervisor);
  EXPECT_EQ(gv.primitives->root(), genome::tree::Type::Behavior);
  EXPECT_EQ(gv.choice_names(), (std::vector<std::string>{"stop_here", "turn(0.5, -0.5)", "go(0.8)"}));
  const auto* turn = std::get_if<control::BehaviorCall>(&gv.behaviors[1].what);
  ASSERT_NE(turn, nullptr);
  EXPECT_EQ(turn->args, (std::vector<double>{0.5, -0.5}));
  EXPECT_EQ(count(*gv.primitives, genome::tree::Kind::Behavior), 3u);
  EXPECT_EQ(count(*gv.primitives, genome::tree::Kind::Wheels), 0u);
}

TEST(GpSyntax, EvolveGpBesideEvolveEs) {
  const CompileResult r = compile_source(kScript, "gp.esc", options());
  ASSERT_TRUE(r.ok()) << rendered(r);
  const eval::ExperimentSpec& x = r.experiments.at(0);
  EXPECT_EQ(es_of(x).mu, 3);
  EXPECT_EQ(x.generations, 4);
  ASSERT_NE(x.tree_operators(), nullptr);
  const gp::GpSettings& s = *x.tree_operators();
  EXPECT_EQ(s.population, 12);
  EXPECT_EQ(s.tournament, 3);
  EXPECT_EQ(s.elitism, 2);
  EXPECT_EQ(s.crossover, 0.7);
  EXPECT_EQ(s.subtree_mutation, 0.1);
  EXPECT_EQ(s.point_mutation, gp::GpSettings{}.point_mutation);   // the default
  EXPECT_EQ(s.init_min_depth, 2);
  EXPECT_EQ(s.init_max_depth, 4);
  EXPECT_EQ(s.max_depth, 9);
  EXPECT_EQ(s.max_size, 60);
  EXPECT_EQ(s.erc_sigma, 0.2);
  EXPECT_EQ(s.generations, 5);
  EXPECT_EQ(x.generations_for(x.controllers[0]), 4);
  EXPECT_EQ(x.generations_for(x.controllers[1]), 5);
  EXPECT_EQ(x.max_generations(), 5);
  EXPECT_EQ(x.total_generations(), 10 * (4 + 3 * 5));   // 10 runs by default
  EXPECT_EQ(x.resolved_settings.at("gp.population"), "12");
  EXPECT_EQ(x.resolved_settings.at("gp.init_depth"), "[2, 4]");
  EXPECT_EQ(x.resolved_settings.at("gp.crossover"), "0.7");
  EXPECT_EQ(x.resolved_settings.at("generations"), "4");      // the ES's, as before
  EXPECT_EQ(x.resolved_settings.at("gp.generations"), "5");
}

TEST(GpSyntax, SetOverridesGpSettingsAndGenerationsOfBoth) {
  const CompileResult r = compile_source(kScript, "gp.esc", options());
  ASSERT_TRUE(r.ok()) << rendered(r);
  eval::ExperimentSpec x = r.experiments.at(0);
  EXPECT_EQ(apply_setting(x, "gp.population", "50"), "");
  EXPECT_EQ(gp_of(x).population, 50);
  EXPECT_EQ(x.resolved_settings.at("gp.population"), "50");
  EXPECT_EQ(apply_setting(x, "gp.init_depth", "[3, 5]"), "");
  EXPECT_EQ(gp_of(x).init_min_depth, 3);
  EXPECT_EQ(gp_of(x).init_max_depth, 5);
  EXPECT_EQ(apply_setting(x, "gp.hoist_mutation", "0"), "");
  EXPECT_EQ(gp_of(x).hoist_mutation, 0.0);
  EXPECT_EQ(apply_setting(x, "generations", "7"), "");
  EXPECT_EQ(x.generations, 7);
  EXPECT_EQ(gp_of(x).generations, 7);
  EXPECT_EQ(x.resolved_settings.at("gp.generations"), "7");

  const eval::ExperimentSpec before = x;
  std::string m = apply_setting(x, "gp.populaton", "5");
  EXPECT_NE(m.find("did you mean `gp.population`?"), std::string::npos) << m;
  m = apply_setting(x, "gp.crossover", "1.5");
  EXPECT_NE(m.find("`crossover` is a probability in [0, 1], found 1.5"), std::string::npos) << m;
  m = apply_setting(x, "gp.max_depth", "1");   // below the shallowest Wheels tree
  EXPECT_NE(m.find("impossible GP settings for tree controller `GW`: max_depth"), std::string::npos) << m;
  m = apply_setting(x, "gp.elitism", "51");
  EXPECT_NE(m.find("elitism"), std::string::npos) << m;
  m = apply_setting(x, "gp.population", "ten");
  EXPECT_NE(m.find("`population` takes a whole number, found `ten`"), std::string::npos) << m;
  EXPECT_EQ(gp_of(x).population, gp_of(before).population);
  EXPECT_EQ(gp_of(x).max_depth, gp_of(before).max_depth);
  EXPECT_EQ(x.resolved_settings, before.resolved_settings);
}

TEST(GpSyntax, GpSettingsOfAnExperimentWithoutGpAreCheckedAndIgnored) {
  const auto r = compile_file(test::source_dir() / "experiments/paper/obstacle_avoidance.esc", options());
  ASSERT_TRUE(r.ok()) << rendered(r);
  eval::ExperimentSpec x = r.experiments.at(0);
  const auto settings = x.resolved_settings;
  EXPECT_EQ(apply_setting(x, "gp.population", "20"), "");   // a dependency of a GP run gets it too
  EXPECT_EQ(x.tree_operators(), nullptr);
  EXPECT_EQ(x.resolved_settings, settings);
  for (const auto& [key, value] : settings) EXPECT_NE(key.rfind("gp.", 0), 0u) << key;
  EXPECT_NE(apply_setting(x, "gp.crossover", "2").find("probability"), std::string::npos);
}

TEST(GpSyntax, TreeSupervisorsOverEvolvedNetworksAreDependencies) {
  const std::string text = R"(
arena r { size 1m x 1m }
fitness f { step: speed }
behavior go(p) { wheels(p, p) }
controller CC = mlp(ir[0..7] -> hidden 3 -> wheels)
experiment basic { arena r  fitness f  compare CC }
behavior avoid = evolved from experiment basic controller CC
primitives p { functions < if  terminals ir[0..7], erc(0, 1) }
controller TV = tree(behaviors [go(0.5), avoid], primitives p)
experiment top { arena r  fitness f  evolve gp(population 10) for 3 generations  compare TV }
)";
  const CompileResult r = compile_source(text, "tv.esc", options());
  ASSERT_TRUE(r.ok()) << rendered(r);
  const eval::ExperimentSpec& top = r.experiments.at(1);
  ASSERT_EQ(top.dependencies.size(), 1u);
  EXPECT_EQ(top.dependencies[0].experiment, "basic");
  EXPECT_EQ(top.dependencies[0].targets.at(0), (std::pair<std::size_t, std::size_t>{0, 1}));
  EXPECT_TRUE(std::holds_alternative<control::FixedController>(top.controllers[0].behaviors[1].what));
}

TEST(GpSyntax, PrimitiveSetErrorsAreReportedOnceAtTheDeclaration) {
  // Both controllers need a Bool for `if` that nothing returns: one error per kind of tree.
  const std::string text = R"(
primitives p { functions + if  terminals ir[0..7] }
controller A = tree(wheels, primitives p)
controller B = tree(wheels, primitives p)
controller C = tree(actions [forward], primitives p)
behavior forward(x) { wheels(x, x) }
)";
  const CompileResult r = compile_source(text, "p.esc", options());
  EXPECT_FALSE(r.ok());
  const std::string out = rendered(r);
  EXPECT_NE(out.find("p.esc:2:12: error: primitive set `p` cannot build a Wheels tree"), std::string::npos) << out;
  EXPECT_NE(out.find("p.esc:2:12: error: primitive set `p` cannot build an Action tree"), std::string::npos) << out;
  EXPECT_NE(out.find("note: used by tree controller `A` here"), std::string::npos) << out;
  EXPECT_NE(out.find("2 errors generated."), std::string::npos) << out;
}

TEST(GpSyntax, NamesAndWordsOfTheNewSyntax) {
  const auto errors = [](const std::string& text) { return rendered(compile_source(text, "w.esc", options())); };
  // `terminals` is an ordinary name elsewhere; `primitives` is a declaration keyword.
  EXPECT_TRUE(compile_source("arena terminals { size 1m x 1m }\narena functions { size 1m x 1m }\n", "w.esc",
                             options()).ok());
  EXPECT_NE(errors("primitives q { functions + terminals ir }\narena q { size 1m x 1m }\n")
                .find("`q` is already declared"),
            std::string::npos);
  EXPECT_NE(errors("primitives q { terminals ir }\ncontroller c = tree(wheels, primitives qq)\n")
                .find("unknown primitive set `qq`; did you mean `q`?"),
            std::string::npos);
  EXPECT_NE(errors("fitness q { step: speed }\ncontroller c = tree(wheels, primitives q)\n")
                .find("`q` is a fitness, not a primitive set"),
            std::string::npos);
  EXPECT_NE(errors("primitives q { functions + + terminals ir }\n").find("`+` is listed twice"), std::string::npos);
  EXPECT_NE(errors("primitives q { terminals speed[0] }\n").find("`speed` is a single value"), std::string::npos);
  EXPECT_NE(errors("primitives q { terminals ir[9] }\n").find("index"), std::string::npos);
}

}  // namespace
}  // namespace esc::compiler
