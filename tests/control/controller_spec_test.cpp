#include "runtime/control/controller_spec.hpp"

#include <gtest/gtest.h>

#include "tests/control/behaviors.hpp"

namespace esc::control {
namespace {

using namespace testing;  // NOLINT

ControllerSpec symbolic_avoider() {
  ControllerSpec s;
  s.name = "sc";
  s.mlp.inputs = ir_inputs();
  s.mlp.hidden = {14};
  s.head = Head::Symbolic;
  s.actions = {forward(), left(), right()};
  return s;
}

TEST(ControllerSpec, PaperSymbolicControllerIs8_14_6With216Weights) {
  const ControllerSpec s = symbolic_avoider();
  EXPECT_EQ(s.output_count(), 6);
  EXPECT_EQ(s.architecture(), "8-14-6");
  EXPECT_EQ(s.genome_size(), 9u * 14u + 15u * 6u);
  EXPECT_EQ(s.genome_size(), 216u);
}

TEST(ControllerSpec, PaperClassicalControllerIs8_20_2With222Weights) {
  ControllerSpec s;
  s.mlp.inputs = ir_inputs();
  s.mlp.hidden = {20};
  EXPECT_EQ(s.output_count(), 2);
  EXPECT_EQ(s.architecture(), "8-20-2");
  EXPECT_EQ(s.genome_size(), 9u * 20u + 21u * 2u);
  EXPECT_EQ(s.genome_size(), 222u);
}

TEST(ControllerSpec, FourActionsWithOneParameterGiveEightOutputs) {
  ControllerSpec s = symbolic_avoider();
  s.actions.push_back(backward());
  EXPECT_EQ(s.output_count(), 8);
  EXPECT_EQ(s.architecture(), "8-14-8");
}

TEST(ControllerSpec, OutputsCountEveryActionsParameters) {
  ControllerSpec s = symbolic_avoider();
  s.actions = {stop(), forward(), spin()};
  EXPECT_EQ(s.output_count(), 3 + 0 + 1 + 2);
}

TEST(ControllerSpec, NoHiddenLayerConnectsInputsToOutputs) {
  ControllerSpec s;
  s.mlp.inputs = ir_inputs();
  EXPECT_EQ(s.architecture(), "8-2");
  EXPECT_EQ(s.genome_size(), 2u * 9u);
}

TEST(ControllerSpec, SeveralHiddenLayersChainTheirSizes) {
  ControllerSpec s;
  s.mlp.inputs = {expr::slot::ir, expr::slot::ir + 1, expr::slot::speed};
  s.mlp.hidden = {5, 4};
  EXPECT_EQ(s.architecture(), "3-5-4-2");
  EXPECT_EQ(s.genome_size(), 5u * 4u + 4u * 6u + 2u * 5u);
}

TEST(RunBehavior, EvaluatesBothWheelsWithTheParameters) {
  expr::Frame f{};
  f[expr::slot::param] = 0.25;
  const WheelCommand c = run_behavior(left(), f);
  EXPECT_DOUBLE_EQ(c.left, -0.25);
  EXPECT_DOUBLE_EQ(c.right, 0.25);
  f[expr::slot::param] = 0.5;
  f[expr::slot::param + 1] = 0.75;
  const WheelCommand s = run_behavior(spin(), f);
  EXPECT_DOUBLE_EQ(s.left, 0.5);
  EXPECT_DOUBLE_EQ(s.right, -0.75);
}

TEST(RunBehavior, ClampsEachWheelToUnitInterval) {
  expr::Frame f{};
  f[expr::slot::param] = 3.0;
  const WheelCommand c = run_behavior(left(), f);
  EXPECT_EQ(c.left, -1.0);
  EXPECT_EQ(c.right, 1.0);
  const Behavior fixed{"fixed", {}, expr::Program::constant(-7.5), expr::Program::constant(0.3)};
  const WheelCommand d = run_behavior(fixed, f);
  EXPECT_EQ(d.left, -1.0);
  EXPECT_DOUBLE_EQ(d.right, 0.3);
}

}  // namespace
}  // namespace esc::control
