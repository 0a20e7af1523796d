// `neat(...)` controllers (docs/language.md, "controller"; docs/neat.md): a NEAT network under
// every head, evolved by NEAT with or without `evolve neat(...)`, beside networks evolved by
// the ES in one experiment; what the run's Problem then carries. The errors are in tests/bad/.
#include <gtest/gtest.h>

#include "helpers.hpp"
#include "runtime/evo/neat/neat_settings.hpp"

namespace esc::compiler {
namespace {

using test::options;
using test::rendered;

constexpr const char* kHead =
    "arena a { size 1m x 1m }\n"
    "fitness f { step: speed }\n"
    "import \"lib/khepera.esc\"\n"
    "controller c = mlp(ir[0..7] -> hidden 4 -> wheels)\n"
    "controller n = neat(ir[0..7] -> wheels)\n"
    "controller s = symbolic(neat(ir[0..7]), actions [forward, left, right])\n"
    "controller v = supervisor(neat(ir[0..7], speed), behaviors [forward(0.5), left(0.3)])\n";

eval::ExperimentSpec compiled(const std::string& experiment) {
  const CompileResult r = compile_source(std::string(kHead) + experiment, "neat.esc", options());
  EXPECT_TRUE(r.ok()) << rendered(r);
  return r.ok() ? r.experiments.at(0) : eval::ExperimentSpec{};
}

std::string algorithm_of(const eval::ExperimentSpec& x, std::size_t i) {
  return std::string(x.evolution_of(x.controllers.at(i)).algorithm->name);
}

TEST(NeatSyntax, NeatNetworksUnderEveryHeadAreNeatsBesideTheEsNetworks) {
  const auto x = compiled("experiment e { arena a  fitness f  evolve es(mu 3, lambda 12) for 7 generations  "
                          "evolve neat(population 30, add_node_prob 0.1)  compare c, n, s, v }");
  ASSERT_EQ(x.controllers.size(), 4u);
  EXPECT_EQ(algorithm_of(x, 0), "es");
  for (std::size_t i = 1; i < 4; ++i) {
    EXPECT_TRUE(x.controllers[i].is_graph()) << i;
    EXPECT_EQ(x.controllers[i].genome_size(), 0u) << i;
    EXPECT_EQ(algorithm_of(x, i), "neat") << i;
    EXPECT_EQ(x.evaluations_per_generation(x.controllers[i]), 30u) << i;
    EXPECT_EQ(x.generations_for(x.controllers[i]), 7) << i;
  }
  EXPECT_EQ(x.controllers[1].architecture(), "8-neat-2");
  EXPECT_EQ(x.controllers[2].architecture(), "8-neat-6");
  EXPECT_EQ(x.controllers[3].architecture(), "9-neat-2");
  const auto& neat = std::any_cast<const evo::NeatSettings&>(x.algorithm_settings.at("neat"));
  EXPECT_DOUBLE_EQ(neat.add_node_prob, 0.1);
  EXPECT_EQ(x.resolved_settings.at("neat.population"), "30");
  // The Problem: a graph of the controller's inputs and outputs, outputs in the head's activation.
  const evo::Problem classical = x.problem_of(x.controllers[1]);
  EXPECT_EQ(classical.kind(), genome::GenomeKind::Graph);
  EXPECT_EQ(classical.graph.inputs, 8u);
  EXPECT_EQ(classical.graph.outputs, 2u);
  EXPECT_EQ(classical.graph.output_activation, genome::graph::Activation::Tanh);
  const evo::Problem symbolic = x.problem_of(x.controllers[2]);
  EXPECT_EQ(symbolic.graph.outputs, 6u);
  EXPECT_EQ(symbolic.graph.output_activation, genome::graph::Activation::Sigmoid);
  EXPECT_EQ(x.problem_of(x.controllers[0]).kind(), genome::GenomeKind::Vector);
}

TEST(NeatSyntax, ANeatNetworkWithoutEvolveNeatRunsWithNeatsDefaults) {
  const auto x = compiled("experiment e { arena a  fitness f  compare n }");
  EXPECT_EQ(algorithm_of(x, 0), "neat");
  EXPECT_EQ(x.evaluations_per_generation(x.controllers[0]), 150u);
}

// NSGA-II, novelty search and MAP-Elites take NEAT networks; `evolve neat(...)` then gives
// the operators that vary them, as `evolve gp(...)` does for trees; CMA-ES does not take them.
TEST(NeatSyntax, OtherSelectionsEvolveNeatNetworksWithNeatsOperators) {
  const auto x = compiled("experiment e { arena a  fitness f  descriptor d: speed in [0, 1]  "
                          "evolve neat(add_node_prob 0.4, start_hidden 2) for 5 generations  evolve nsga2(population 10)  "
                          "compare n by nsga2, n by novelty as n2, n by map_elites as n3 }");
  ASSERT_EQ(x.controllers.size(), 3u);
  EXPECT_EQ(algorithm_of(x, 0), "nsga2");
  EXPECT_EQ(algorithm_of(x, 1), "novelty");
  EXPECT_EQ(algorithm_of(x, 2), "map_elites");
  for (const auto& c : x.controllers) {
    const evo::Problem p = x.problem_of(c);
    EXPECT_EQ(p.kind(), genome::GenomeKind::Graph);
    EXPECT_DOUBLE_EQ(p.graph.operators.add_node_prob, 0.4);
    EXPECT_EQ(p.graph.operators.start_hidden, 2);
    EXPECT_EQ(x.generations_for(c), 5);
  }
  // Without `evolve neat`, NEAT's defaults vary them.
  const auto d = compiled("experiment e { arena a  fitness f  evolve nsga2(population 10)  compare n by nsga2 }");
  EXPECT_EQ(d.problem_of(d.controllers[0]).graph.operators, evo::graph_operators(evo::NeatSettings{}));
}

}  // namespace
}  // namespace esc::compiler
