// The round trip of the GP issue: a tree evolved from a script, printed as script code and
// pasted into another script as a hand-written behavior, scores exactly the fitness the
// tree scored, on the same evaluation stream. For a Wheels tree the printed behavior is
// the tree itself; for an Action tree (the GP twin of a symbolic controller) it is the
// tree with its actions' wheel commands inlined (runtime/tree_control/inline_actions.hpp).
// The pasted behavior is run by a supervisor with that one behavior (it always acts).
#include <gtest/gtest.h>

#include "helpers.hpp"
#include "runtime/control/controller.hpp"
#include "runtime/eval/campaign.hpp"
#include "runtime/genome/tree/codec.hpp"
#include "runtime/genome/tree/init.hpp"
#include "runtime/genome/tree/print.hpp"
#include "runtime/tree_control/inline_actions.hpp"
#include "runtime/tree_control/tree_driver.hpp"
#include "tests/gp/helpers.hpp"

namespace esc::compiler {
namespace {

using test::options;
using test::rendered;
using test::source_dir;

eval::ExperimentSpec shortened(const std::filesystem::path& script) {
  const CompileResult r = compile_file(script, options());
  EXPECT_TRUE(r.ok()) << rendered(r);
  eval::ExperimentSpec x = r.experiments.at(0);
  for (const auto& [k, v] : std::vector<std::pair<std::string, std::string>>{
           {"runs", "1"}, {"generations", "4"}, {"epochs", "3"}, {"gp.population", "30"}, {"gp.max_size", "60"}})
    EXPECT_EQ(apply_setting(x, k, v), "") << k;
  return x;
}

// The script text a user gets for the tree: a behavior declaration.
std::string printed_behavior(const control::ControllerSpec& c, const genome::tree::Tree& tree) {
  if (c.head == control::Head::Classical) return genome::tree::behavior_script(tree, *c.primitives, "pasted");
  const tree_control::InlinedTree inlined = tree_control::inline_actions(tree, *c.primitives, c.actions);
  return genome::tree::behavior_script(inlined.tree, inlined.set, "pasted");
}

// Compiles `behavior` into a script of its own and returns the supervisor that runs it.
control::ControllerSpec pasted(const std::string& behavior) {
  const std::string text = "import \"../paper/obstacle_avoidance.esc\"\n" + behavior +
                           "\ncontroller P = supervisor(mlp(ir[0]), behaviors [pasted])\n"
                           "experiment paste { arena nolfi  fitness forward_avoid  compare P }\n";
  const CompileResult r = compile_source(text, source_dir() / "experiments/gp/pasted.esc", options());
  EXPECT_TRUE(r.ok()) << rendered(r) << "\n" << behavior;
  return r.ok() ? r.experiments.at(0).controllers.at(0) : control::ControllerSpec{};
}

double pasted_fitness(eval::Evaluator& ev, const std::string& behavior, std::uint64_t seed) {
  const control::ControllerSpec p = pasted(behavior);
  if (p.behaviors.empty()) return -1.0;
  return ev.evaluate(p, std::vector<double>(p.genome_size(), 0.0), seed).fitness;
}

TEST(GpRoundTrip, ThePastedBestTreeScoresExactlyItsFitness) {
  const eval::ExperimentSpec x = shortened(source_dir() / "experiments/gp/obstacle_avoidance_gp.esc");
  ASSERT_EQ(x.controllers.size(), 2u);   // GW (Wheels), GS (Action)
  eval::CampaignListener quiet;
  const eval::CampaignResult res = eval::run_campaign(x, {2}, quiet);
  eval::Evaluator ev(x);
  for (std::size_t c = 0; c < 2; ++c) {
    const control::ControllerSpec& spec = x.controllers[c];
    const eval::RunResult& run = res.controllers[c].runs.at(0);
    const genome::tree::Tree tree = genome::tree::decode(run.best_genome, *spec.primitives);
    const std::string behavior = printed_behavior(spec, tree);
    // What the run directory offers to paste is this behavior.
    EXPECT_EQ(behavior, "behavior pasted() { " + run.best_behavior + " }");
    const std::uint64_t seed =
        eval::evaluation_seed(run.seed, run.best_generation, static_cast<std::size_t>(run.best_index));
    EXPECT_EQ(pasted_fitness(ev, behavior, seed), run.best_fitness) << spec.name << ": " << behavior;
    EXPECT_GT(run.best_fitness, 0.0);
  }
}

TEST(GpRoundTrip, RandomTreesOfBothRootsGiveTheSameCommandsAndFitness) {
  // Deeper and bushier than a short run's best: every operator, nested if-then-else,
  // protected division, random constants with all their digits; on random frames (zeros,
  // ones and huge values mixed in) and in the simulator.
  const eval::ExperimentSpec x = shortened(source_dir() / "experiments/gp/obstacle_avoidance_gp.esc");
  eval::Evaluator ev(x);
  Rng rng(2003);
  for (const control::ControllerSpec& spec : x.controllers) {
    for (int i = 0; i < 12; ++i) {
      const genome::tree::Tree tree = i % 2 == 0 ? genome::tree::full(*spec.primitives, spec.primitives->root(), 3 + i % 4, rng)
                                       : genome::tree::grow(*spec.primitives, spec.primitives->root(), 7, rng);
      const std::string behavior = printed_behavior(spec, tree);
      const control::ControllerSpec p = pasted(behavior);
      ASSERT_FALSE(p.behaviors.empty()) << behavior;
      const std::vector<double> zeros(p.genome_size(), 0.0);
      control::Controller hand_written(p, zeros);
      tree_control::TreeDriver evolved(spec, tree);
      for (int f = 0; f < 200; ++f) {
        expr::Frame a = genome::tree::test::random_frame(rng);
        expr::Frame b = a;
        const control::WheelCommand want = evolved.step(a);
        const control::WheelCommand got = hand_written.step(b);
        ASSERT_EQ(got.left, want.left) << behavior;
        ASSERT_EQ(got.right, want.right) << behavior;
      }
      const std::uint64_t seed = 1000 + static_cast<std::uint64_t>(i);
      EXPECT_EQ(ev.evaluate(p, zeros, seed).fitness, ev.evaluate(spec, tree, seed).fitness) << behavior;
    }
  }
}

}  // namespace
}  // namespace esc::compiler
