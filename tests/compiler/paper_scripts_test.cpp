// The paper's scripts compile to the experiments of the paper, and every shipped script
// compiles cleanly.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "helpers.hpp"
#include "runtime/expr/observables.hpp"
#include "tests/algorithm_settings.hpp"

namespace esc::compiler {
namespace {

using test::options;
using test::rendered;
using test::source_dir;

// Weights of an MLP (bias + one weight per input for every neuron), computed here so the
// test does not depend on the control library.
std::size_t weights(const control::ControllerSpec& c) {
  std::size_t outputs = 2;
  if (c.head == control::Head::Symbolic) {
    outputs = c.actions.size();
    for (const auto& a : c.actions) outputs += a.params.size();
  }
  std::size_t in = c.mlp.inputs.size(), total = 0;
  for (int h : c.mlp.hidden) {
    total += static_cast<std::size_t>(h) * (in + 1);
    in = static_cast<std::size_t>(h);
  }
  return total + outputs * (in + 1);
}

const control::ControllerSpec& find(const eval::ExperimentSpec& x, const std::string& name) {
  for (const auto& c : x.controllers)
    if (c.name == name) return c;
  throw std::runtime_error("no controller " + name);
}

TEST(PaperScripts, ObstacleAvoidanceCompilesToTheSectionThreeSetup) {
  const auto r = compile_file(source_dir() / "experiments/paper/obstacle_avoidance.esc", options());
  ASSERT_TRUE(r.ok()) << rendered(r);
  ASSERT_EQ(r.experiments.size(), 2u);
  const eval::ExperimentSpec& x = r.experiments[0];
  EXPECT_EQ(x.name, "obstacle_avoidance");   // the default experiment comes first
  EXPECT_EQ(r.experiments[1].name, "obstacle_avoidance_constrained");

  EXPECT_DOUBLE_EQ(x.arena.width_m, 0.6);
  EXPECT_DOUBLE_EQ(x.arena.height_m, 0.6);
  ASSERT_EQ(x.arena.cylinders.size(), 3u);
  EXPECT_DOUBLE_EQ(x.arena.cylinders[0].center_m.x, 0.2);
  EXPECT_DOUBLE_EQ(x.arena.cylinders[0].center_m.y, 0.4);
  EXPECT_DOUBLE_EQ(x.arena.cylinders[0].radius_m, 0.025);
  EXPECT_FALSE(x.arena.fixed_start.has_value());

  EXPECT_EQ(x.epochs, 10);
  EXPECT_EQ(x.steps, 150);
  EXPECT_EQ(x.runs, 10);
  EXPECT_EQ(x.seed, 1u);
  EXPECT_TRUE(x.robot.motor.inertia);
  EXPECT_EQ(es_of(x).mu, 30);
  EXPECT_EQ(es_of(x).lambda, 150);
  EXPECT_EQ(es_of(x).selection, evo::Selection::Comma);
  EXPECT_EQ(es_of(x).recombination, evo::Recombination::Intermediate);
  EXPECT_EQ(es_of(x).step_sizes, evo::StepSizes::PerGene);
  EXPECT_DOUBLE_EQ(es_of(x).lower, -1.0);
  EXPECT_DOUBLE_EQ(es_of(x).upper, 1.0);
  EXPECT_EQ(x.generations, 250);

  // Table 1's three pairs: 8-2 / 8-6, 8-8-2 / 8-8-6, 8-20-2 / 8-14-6.
  ASSERT_EQ(x.controllers.size(), 6u);
  const std::vector<std::pair<std::string, std::size_t>> sizes = {
      {"CC_8_2", 18}, {"SC_8_6", 54}, {"CC_8_8_2", 90}, {"SC_8_8_6", 126}, {"CC_8_20_2", 222}, {"SC_8_14_6", 216}};
  for (const auto& [name, n] : sizes) EXPECT_EQ(weights(find(x, name)), n) << name;
  const auto& sc = find(x, "SC_8_14_6");
  EXPECT_EQ(sc.head, control::Head::Symbolic);
  ASSERT_EQ(sc.mlp.inputs.size(), 8u);
  for (expr::Slot i = 0; i < 8; ++i) EXPECT_EQ(sc.mlp.inputs[i], expr::slot::ir + i);
  EXPECT_EQ(sc.mlp.hidden, std::vector<int>{14});
  ASSERT_EQ(sc.actions.size(), 3u);
  EXPECT_EQ(sc.actions[0].name, "forward");
  EXPECT_EQ(sc.actions[1].name, "left");
  EXPECT_EQ(sc.actions[2].name, "right");
  const auto& cc = find(x, "CC_8_20_2");
  EXPECT_EQ(cc.head, control::Head::Classical);
  EXPECT_EQ(cc.mlp.hidden, std::vector<int>{20});
  EXPECT_TRUE(find(x, "CC_8_2").mlp.hidden.empty());

  // The forward-only fitness on the physical speeds, ending the epoch on a collision.
  expr::Frame f{};
  f[expr::slot::forward_speed] = 0.8;
  f[expr::slot::wheel_diff] = 0.25;
  EXPECT_DOUBLE_EQ(x.fitness.step.eval(f), 0.8 * (1 - 0.5));
  f[expr::slot::forward_speed] = -0.8;
  EXPECT_DOUBLE_EQ(x.fitness.step.eval(f), 0.0);
  ASSERT_EQ(x.fitness.stop_when.size(), 1u);
  f[expr::slot::collision] = 1.0;
  EXPECT_EQ(x.fitness.stop_when[0].eval(f), 1.0);

  // The constrained arena is a corridor: about three body widths across, a long straight run.
  const eval::ExperimentSpec& y = r.experiments[1];
  EXPECT_DOUBLE_EQ(y.arena.width_m, 1.2);
  EXPECT_DOUBLE_EQ(y.arena.height_m, 0.15);
  EXPECT_EQ(y.arena.cylinders.size() + y.arena.boxes.size(), 0u);
  ASSERT_EQ(y.controllers.size(), 2u);
  EXPECT_EQ(weights(y.controllers[1]), 216u);

  EXPECT_EQ(x.resolved_settings.at("epochs"), "10");
  EXPECT_EQ(x.resolved_settings.at("mu"), "30");
  EXPECT_EQ(x.resolved_settings.at("selection"), "comma");
  EXPECT_EQ(x.resolved_settings.at("arena"), "nolfi");
  EXPECT_EQ(x.resolved_settings.at("robot.inertia"), "on");
  EXPECT_EQ(x.resolved_settings.at("robot.max_speed"), "0.08 m/s");
  EXPECT_EQ(x.resolved_settings.at("fitness"), "forward_avoid");
  EXPECT_EQ(x.resolved_settings.at("fitness.step"), "max(forward_speed, 0) * (1 - sqrt(wheel_diff))");
}

TEST(PaperScripts, LoopholeHasBackwardAndBothSimulators) {
  const auto r = compile_file(source_dir() / "experiments/paper/loophole.esc", options());
  ASSERT_TRUE(r.ok()) << rendered(r);
  ASSERT_EQ(r.experiments.size(), 3u);
  EXPECT_EQ(r.experiments[0].name, "loophole_no_inertia");
  EXPECT_FALSE(r.experiments[0].robot.motor.inertia);
  EXPECT_EQ(r.experiments[1].name, "loophole_inertia");
  EXPECT_TRUE(r.experiments[1].robot.motor.inertia);
  // The paper's condition for a CC to find the trick: genes in [-10, 10], 20 and 30 hidden.
  const eval::ExperimentSpec& wide = r.experiments[2];
  EXPECT_EQ(wide.name, "loophole_wide_weights");
  EXPECT_FALSE(wide.robot.motor.inertia);
  EXPECT_EQ(wide.resolved_settings.at("bounds"), "[-10, 10]");
  EXPECT_EQ(weights(find(wide, "CC30")), 30u * 9 + 2u * 31);   // 8-30-2
  EXPECT_EQ(weights(find(r.experiments[0], "SC4_0")), 8u * 9);    // 8-8: 4 choices and their 4 parameters
  const auto& sc4 = find(r.experiments[0], "SC4");
  ASSERT_EQ(sc4.actions.size(), 4u);
  EXPECT_EQ(weights(sc4), 14u * 9 + 8u * 15);   // 8-14-8
  // The actions are the library's behaviors: backward(p) = wheels(-p, -p).
  const control::Behavior& back = sc4.actions[3];
  EXPECT_EQ(back.name, "backward");
  expr::Frame f{};
  f[expr::slot::param] = 0.7;
  EXPECT_DOUBLE_EQ(back.left.eval(f), -0.7);
  EXPECT_DOUBLE_EQ(back.right.eval(f), -0.7);
  // The original fitness rewards speed in any direction.
  f[expr::slot::speed] = 1.0;
  f[expr::slot::forward_speed] = -1.0;
  EXPECT_DOUBLE_EQ(r.experiments[0].fitness.step.eval(f), 1.0);
}

TEST(PaperScripts, EveryShippedScriptCompilesCleanly) {
  int count = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(source_dir() / "experiments")) {
    if (e.path().extension() != ".esc") continue;
    ++count;
    const auto r = compile_file(e.path(), options());
    EXPECT_TRUE(r.ok()) << e.path() << "\n" << rendered(r);
    EXPECT_TRUE(r.diagnostics.empty()) << rendered(r);
  }
  EXPECT_GE(count, 4);
}

TEST(PaperScripts, ExamplesUseUnitsAndDerivedRobots) {
  const auto r = compile_file(source_dir() / "experiments/examples/custom_behaviors.esc", options());
  ASSERT_TRUE(r.ok()) << rendered(r);
  ASSERT_EQ(r.experiments.size(), 1u);
  const auto& x = r.experiments[0];
  EXPECT_DOUBLE_EQ(x.robot.motor.max_speed_mps, 0.05);
  EXPECT_DOUBLE_EQ(x.robot.motor.time_constant_s, 0.15);
  EXPECT_DOUBLE_EQ(x.robot.motor.max_accel_mps2, 0.5);
  EXPECT_DOUBLE_EQ(x.arena.width_m, 1.0);
  ASSERT_EQ(x.arena.boxes.size(), 1u);
  EXPECT_NEAR(x.arena.boxes[0].angle_rad, 30 * 3.14159265358979 / 180, 1e-12);
  ASSERT_TRUE(x.arena.fixed_start.has_value());
  EXPECT_DOUBLE_EQ(x.arena.fixed_start->x_m, 0.1);
  EXPECT_EQ(es_of(x).selection, evo::Selection::Plus);
  EXPECT_EQ(es_of(x).recombination, evo::Recombination::Discrete);
  EXPECT_EQ(es_of(x).step_sizes, evo::StepSizes::One);
  EXPECT_DOUBLE_EQ(es_of(x).initial_sigma, 0.2);
  EXPECT_EQ(x.generations, 30);
  EXPECT_EQ(x.epochs, 4);
  EXPECT_EQ(x.steps, 200);
  EXPECT_EQ(x.controllers[0].mlp.inputs.size(), 9u);   // ir[0..7], speed
  EXPECT_EQ(x.controllers[0].actions[2].params.size(), 0u);
}

TEST(Imports, EachFileOnceAndDiagnosticsCarryTheImportedPath) {
  const auto dir = std::filesystem::temp_directory_path() / "esc_compiler_imports";
  std::filesystem::create_directories(dir / "lib");
  std::ofstream(dir / "lib/a.esc") << "import \"b.esc\"\nbehavior go(p) { wheels(p, p) }\n";
  std::ofstream(dir / "lib/b.esc") << "import \"a.esc\"\nfitness bad { step: sped }\n";   // a cycle
  std::ofstream(dir / "main.esc") << "import \"lib/a.esc\"\nimport \"lib/b.esc\"\n";
  const auto r = compile_file(dir / "main.esc", CompileOptions{});
  ASSERT_FALSE(r.ok());
  ASSERT_EQ(r.diagnostics.size(), 1u) << rendered(r);   // b.esc loaded once: one error
  EXPECT_EQ(r.diagnostics[0].where.file, (dir / "lib/b.esc").lexically_normal());
  EXPECT_EQ(r.diagnostics[0].where.line, 2);
  EXPECT_NE(rendered(r).find("did you mean `speed`?"), std::string::npos);

  const auto missing = compile_source("import \"nope.esc\"\n", dir / "m.esc", options());
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.diagnostics[0].message.find("cannot find `nope.esc`; searched:"), std::string::npos);
  EXPECT_EQ(missing.diagnostics[0].where.column, 8);
  std::filesystem::remove_all(dir);
}

TEST(Imports, SearchPathFindsTheLibrary) {
  const auto r = compile_source("import \"lib/khepera.esc\"\n"
                                "arena a { size 1m x 1m }\n"
                                "fitness f { step: speed }\n"
                                "controller s = symbolic(mlp(ir[0..7] -> hidden 2), actions [forward, backward])\n"
                                "experiment e { arena a  robot khepera  fitness f  compare s }\n",
                                "/nonexistent/dir/script.esc", options());
  ASSERT_TRUE(r.ok()) << rendered(r);
  EXPECT_EQ(r.experiments[0].controllers[0].actions.size(), 2u);
}

}  // namespace
}  // namespace esc::compiler
