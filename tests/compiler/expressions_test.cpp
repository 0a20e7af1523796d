// Expressions lower to programs that compute what they say.
#include <gtest/gtest.h>

#include <cmath>

#include "helpers.hpp"
#include "runtime/expr/observables.hpp"

namespace esc::compiler {
namespace {

using test::options;
using test::rendered;
using test::with_step;

expr::Program step_program(const std::string& step) {
  const auto r = compile_source(with_step(step), "expr.esc", options());
  EXPECT_TRUE(r.ok()) << step << "\n" << rendered(r);
  if (!r.ok() || r.experiments.empty()) return expr::Program::constant(std::nan(""));
  return r.experiments[0].fitness.step;
}

expr::Frame sample_frame() {
  expr::Frame f{};
  f[expr::slot::speed] = 0.6;
  f[expr::slot::forward_speed] = 0.4;
  f[expr::slot::wheel_diff] = 0.09;
  f[expr::slot::wheels] = 0.7;
  f[expr::slot::wheels + 1] = -0.2;
  for (expr::Slot i = 0; i < expr::kIrCount; ++i) f[expr::slot::ir + i] = 0.1 * i;
  f[expr::slot::collision] = 0.0;
  f[expr::slot::step] = 12;
  f[expr::slot::time] = 1.2;
  f[expr::slot::epoch] = 3;
  return f;
}

TEST(Expressions, EvaluateToTheirValue) {
  const expr::Frame f = sample_frame();
  const double fs = 0.4, wd = 0.09, sp = 0.6;
  const std::vector<std::pair<std::string, double>> cases = {
      {"forward_speed", fs},
      {"1 + 2 * 3", 7},
      {"(1 + 2) * 3", 9},
      {"2 ^ 3 ^ 2", 512},
      {"-2 ^ 2", -4},
      {"10 - 4 - 3", 3},
      {"8 / 4 / 2", 1},
      {"max(forward_speed, 0) * (1 - sqrt(wheel_diff))", fs * (1 - std::sqrt(wd))},
      {"min(speed, 0.3) + max(wheels[0], wheels[1])", 0.3 + 0.7},
      {"abs(wheels[1])", 0.2},
      {"clamp(wheels[0], -0.5, 0.5)", 0.5},
      {"if ir[3] > 0.25 then 1 else 2", 1},
      {"if ir[2] > 0.25 then 1 else 2", 2},
      {"if collision then -1 else if speed > 0.5 then 1 else 0", 1},
      {"10cm", 0.1},
      {"time > 1s and step >= 12", 1},
      {"time > 1500ms or not collision", 1},
      {"not (speed < 0.5)", 1},
      {"speed == 0.6 and epoch != 2", 1},
      {"90deg", std::acos(-1.0) / 2},
      {"sigmoid(0) + tanh(0) + exp(0) + log(1)", 1.5},
      {"ir[7] / 0", 0.0},   // total division
      {"sqrt(-1)", 0.0},
      {"true + false", 1},
      {"2.5e-1 * 4", 1},
      {"+speed", sp},
  };
  for (const auto& [text, want] : cases) {
    const expr::Program p = step_program(text);
    EXPECT_NEAR(p.eval(f), want, 1e-12) << text << " -> " << p.disassemble();
  }
}

TEST(Expressions, ConstantsAreFolded) {
  EXPECT_EQ(step_program("1 + 2 * 3").code().size(), 1u);
  EXPECT_EQ(step_program("speed * (2 + 3)").disassemble(), step_program("speed * 5").disassemble());
  EXPECT_EQ(step_program("if 1 > 0 then speed else wheel_diff").disassemble(), step_program("speed").disassemble());
}

TEST(Expressions, AddingAFitnessTermChangesTheProgramAsWritten) {
  const expr::Frame f = sample_frame();
  const expr::Program a = step_program("forward_speed");
  const expr::Program b = step_program("forward_speed + 0.5 * ir[3]");
  EXPECT_DOUBLE_EQ(a.eval(f), 0.4);
  EXPECT_DOUBLE_EQ(b.eval(f), 0.4 + 0.5 * 0.3);
  EXPECT_EQ(b.disassemble(), a.disassemble() + " const 0.5 load " + std::to_string(expr::slot::ir + 3) + " mul add");
}

TEST(Expressions, BehaviorParametersReadParamSlots) {
  const auto r = compile_source("behavior turn(a, b) { wheels(a - b, clamp(b * 2, -1, 1)) }\n"
                                "arena x { size 1m x 1m }\n"
                                "fitness f { step: speed }\n"
                                "controller c = symbolic(mlp(ir[0..7]), actions [turn])\n"
                                "experiment e { arena x  fitness f  compare c }\n",
                                "b.esc", options());
  ASSERT_TRUE(r.ok()) << rendered(r);
  const control::Behavior& b = r.experiments[0].controllers[0].actions[0];
  EXPECT_EQ(b.params, (std::vector<std::string>{"a", "b"}));
  expr::Frame f{};
  f[expr::slot::param] = 0.9;
  f[expr::slot::param + 1] = 0.3;
  EXPECT_DOUBLE_EQ(b.left.eval(f), 0.6);
  EXPECT_DOUBLE_EQ(b.right.eval(f), 0.6);
}

TEST(Expressions, ErrorsAreLocatedAndOneEach) {
  const auto r = compile_source(with_step("sped + foo(1) + ir[9] + wheels"), "e.esc", options());
  ASSERT_FALSE(r.ok());
  ASSERT_EQ(r.diagnostics.size(), 4u) << rendered(r);
  EXPECT_EQ(r.diagnostics[0].where.line, 2);
  EXPECT_EQ(r.diagnostics[0].where.column, 19);
  EXPECT_NE(r.diagnostics[0].message.find("did you mean `speed`?"), std::string::npos);
}

}  // namespace
}  // namespace esc::compiler
