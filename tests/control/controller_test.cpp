#include "runtime/control/controller.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/control/behaviors.hpp"

namespace esc::control {
namespace {

using namespace testing;  // NOLINT

double logistic(double x) { return 1.0 / (1.0 + std::exp(-x)); }

// Two IR inputs, two hidden neurons, classical head: 2*3 + 2*3 = 12 weights.
ControllerSpec tiny_classical(Activation hidden = Activation::Tanh) {
  ControllerSpec s;
  s.name = "tiny";
  s.mlp.inputs = {expr::slot::ir, expr::slot::ir + 1};
  s.mlp.hidden = {2};
  s.mlp.hidden_activation = hidden;
  return s;
}

// Neuron by neuron, bias first: hidden 0, hidden 1, output 0, output 1.
const std::vector<double> kTinyGenome = {0.1,  0.5, -0.3,  -0.2, 0.4, 0.8,
                                         0.05, 1.0, -0.5,  -0.1, 0.3, 0.7};

TEST(Controller, ClassicalOutputMatchesHandComputation) {
  const ControllerSpec spec = tiny_classical();
  ASSERT_EQ(spec.genome_size(), kTinyGenome.size());
  Controller c(spec, kTinyGenome);
  expr::Frame f{};
  f[expr::slot::ir] = 0.6;
  f[expr::slot::ir + 1] = 0.2;
  const WheelCommand w = c.step(f);

  const double h0 = std::tanh(0.1 + 0.5 * 0.6 - 0.3 * 0.2);
  const double h1 = std::tanh(-0.2 + 0.4 * 0.6 + 0.8 * 0.2);
  EXPECT_NEAR(w.left, std::tanh(0.05 + 1.0 * h0 - 0.5 * h1), 1e-14);
  EXPECT_NEAR(w.right, std::tanh(-0.1 + 0.3 * h0 + 0.7 * h1), 1e-14);
  EXPECT_EQ(c.last_action(), -1);
}

TEST(Controller, HiddenActivationFollowsTheSpec) {
  expr::Frame f{};
  f[expr::slot::ir] = 0.6;
  f[expr::slot::ir + 1] = 0.2;
  const double a0 = 0.1 + 0.5 * 0.6 - 0.3 * 0.2;
  const double a1 = -0.2 + 0.4 * 0.6 + 0.8 * 0.2;

  const ControllerSpec lin = tiny_classical(Activation::Linear);
  Controller cl(lin, kTinyGenome);
  const WheelCommand wl = cl.step(f);
  EXPECT_NEAR(wl.left, std::tanh(0.05 + a0 - 0.5 * a1), 1e-14);
  EXPECT_NEAR(wl.right, std::tanh(-0.1 + 0.3 * a0 + 0.7 * a1), 1e-14);

  const ControllerSpec sig = tiny_classical(Activation::Sigmoid);
  Controller cs(sig, kTinyGenome);
  const WheelCommand ws = cs.step(f);
  const double h0 = logistic(a0);
  const double h1 = logistic(a1);
  EXPECT_NEAR(ws.left, std::tanh(0.05 + h0 - 0.5 * h1), 1e-14);
  EXPECT_NEAR(ws.right, std::tanh(-0.1 + 0.3 * h0 + 0.7 * h1), 1e-14);
}

TEST(Controller, NoHiddenLayerIsOneProduct) {
  ControllerSpec s;
  s.mlp.inputs = {expr::slot::speed};
  const std::vector<double> g = {0.2, 0.5, -0.1, -2.0};
  Controller c(s, g);
  expr::Frame f{};
  f[expr::slot::speed] = 0.4;
  const WheelCommand w = c.step(f);
  EXPECT_NEAR(w.left, std::tanh(0.2 + 0.5 * 0.4), 1e-15);
  EXPECT_NEAR(w.right, std::tanh(-0.1 - 2.0 * 0.4), 1e-15);
}

// One input (ir[0]), no hidden layer, actions forward, left, right: 6 outputs, 12 genes.
// Output j has bias genome[2j] and weight genome[2j + 1].
ControllerSpec tiny_symbolic() {
  ControllerSpec s;
  s.name = "tiny_sc";
  s.mlp.inputs = {expr::slot::ir};
  s.head = Head::Symbolic;
  s.actions = {forward(), left(), right()};
  return s;
}

const std::vector<double> kSymbolicGenome = {
    0.0,  -4.0,  // forward chooser: falls with ir[0]
    0.0,  4.0,   // left chooser: rises with ir[0]
    -1.0, 0.0,   // right chooser: constant, never the best here
    1.0,  0.0,   // forward's p
    -0.5, 0.0,   // left's p
    2.0,  0.0,   // right's p
};

TEST(Controller, SymbolicHeadRunsTheArgmaxActionWithItsParameter) {
  const ControllerSpec spec = tiny_symbolic();
  ASSERT_EQ(spec.genome_size(), kSymbolicGenome.size());
  Controller c(spec, kSymbolicGenome);
  expr::Frame f{};
  f[expr::slot::ir] = 0.5;  // choosers: logistic(-2), logistic(2), logistic(-1) -> left
  const WheelCommand w = c.step(f);
  const double p = logistic(-0.5);
  EXPECT_EQ(c.last_action(), 1);
  EXPECT_DOUBLE_EQ(f[expr::slot::param], p);
  EXPECT_DOUBLE_EQ(w.left, -p);
  EXPECT_DOUBLE_EQ(w.right, p);

  f[expr::slot::ir] = -0.5;  // forward now wins, with its own parameter
  const WheelCommand w2 = c.step(f);
  EXPECT_EQ(c.last_action(), 0);
  EXPECT_DOUBLE_EQ(f[expr::slot::param], logistic(1.0));
  EXPECT_DOUBLE_EQ(w2.left, logistic(1.0));
  EXPECT_DOUBLE_EQ(w2.right, logistic(1.0));
}

TEST(Controller, SymbolicHeadPicksTheLastActionWhenItIsBest) {
  std::vector<double> g = kSymbolicGenome;
  g[4] = 5.0;  // right's chooser bias
  const ControllerSpec spec = tiny_symbolic();
  Controller c(spec, g);
  expr::Frame f{};
  f[expr::slot::ir] = 0.5;
  const WheelCommand w = c.step(f);
  EXPECT_EQ(c.last_action(), 2);
  EXPECT_DOUBLE_EQ(w.left, logistic(2.0));
  EXPECT_DOUBLE_EQ(w.right, -logistic(2.0));
}

TEST(Controller, SymbolicTieGoesToTheFirstAction) {
  const ControllerSpec spec = tiny_symbolic();
  Controller c(spec, kSymbolicGenome);
  expr::Frame f{};
  f[expr::slot::ir] = 0.0;  // forward and left choosers both logistic(0) = 0.5
  const WheelCommand w = c.step(f);
  EXPECT_EQ(c.last_action(), 0);
  EXPECT_DOUBLE_EQ(w.left, logistic(1.0));

  // Reorder so left comes first: the tie now goes to left.
  ControllerSpec swapped = spec;
  swapped.actions = {left(), forward(), right()};
  Controller c2(swapped, kSymbolicGenome);
  const WheelCommand w2 = c2.step(f);
  EXPECT_EQ(c2.last_action(), 0);
  EXPECT_DOUBLE_EQ(w2.left, -logistic(1.0));  // action 0's parameter output is output 3
  EXPECT_DOUBLE_EQ(w2.right, logistic(1.0));
}

TEST(Controller, ParametersFollowTheActionsInOrderWhateverTheirCounts) {
  // stop() has no parameter, forward(p) one, spin(a, b) two: outputs are
  // [choose stop, choose forward, choose spin, forward.p, spin.a, spin.b].
  ControllerSpec s;
  s.mlp.inputs = {expr::slot::ir};
  s.head = Head::Symbolic;
  s.actions = {stop(), forward(), spin()};
  ASSERT_EQ(s.output_count(), 6);
  const std::vector<double> g = {0.0, 0.0, 0.0, 0.0, 3.0, 0.0,
                                 0.9, 0.0, 0.4, 0.0, -0.4, 0.0};
  Controller c(s, g);
  expr::Frame f{};
  const WheelCommand w = c.step(f);
  EXPECT_EQ(c.last_action(), 2);
  EXPECT_DOUBLE_EQ(f[expr::slot::param], logistic(0.4));
  EXPECT_DOUBLE_EQ(f[expr::slot::param + 1], logistic(-0.4));
  EXPECT_DOUBLE_EQ(w.left, logistic(0.4));
  EXPECT_DOUBLE_EQ(w.right, -logistic(-0.4));

  std::vector<double> g_stop = g;
  g_stop[0] = 5.0;
  Controller cs(s, g_stop);
  const WheelCommand ws = cs.step(f);
  EXPECT_EQ(cs.last_action(), 0);
  EXPECT_EQ(ws.left, 0.0);
  EXPECT_EQ(ws.right, 0.0);
}

TEST(Controller, PaperArchitectureRunsAndStaysInRange) {
  ControllerSpec s;
  s.mlp.inputs = ir_inputs();
  s.mlp.hidden = {14};
  s.head = Head::Symbolic;
  s.actions = {forward(), left(), right(), backward()};
  std::vector<double> g(s.genome_size());
  for (std::size_t i = 0; i < g.size(); ++i) g[i] = std::sin(static_cast<double>(i) * 1.7);
  Controller c(s, g);
  expr::Frame f{};
  for (int t = 0; t < 50; ++t) {
    for (expr::Slot i = 0; i < expr::kIrCount; ++i)
      f[expr::slot::ir + i] = 0.5 + 0.5 * std::sin(0.3 * t + i);
    const WheelCommand w = c.step(f);
    EXPECT_GE(c.last_action(), 0);
    EXPECT_LT(c.last_action(), 4);
    EXPECT_GE(w.left, -1.0);
    EXPECT_LE(w.left, 1.0);
    EXPECT_GE(w.right, -1.0);
    EXPECT_LE(w.right, 1.0);
  }
}

TEST(Controller, WrongGenomeSizeThrowsWithBothSizes) {
  ControllerSpec s;
  s.name = "sc";
  s.mlp.inputs = ir_inputs();
  s.mlp.hidden = {14};
  s.head = Head::Symbolic;
  s.actions = {forward(), left(), right()};
  const std::vector<double> g(215);
  try {
    Controller c(s, g);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("216"), std::string::npos) << msg;
    EXPECT_NE(msg.find("215"), std::string::npos) << msg;
    EXPECT_NE(msg.find("8-14-6"), std::string::npos) << msg;
  }
  const std::vector<double> longer(217);
  EXPECT_THROW(Controller(s, longer), std::invalid_argument);
}

TEST(Controller, RejectsSpecsItCannotRun) {
  ControllerSpec no_actions = tiny_symbolic();
  no_actions.actions.clear();
  const std::vector<double> g0(no_actions.genome_size());
  EXPECT_THROW(Controller(no_actions, g0), std::invalid_argument);

  ControllerSpec too_many = tiny_symbolic();
  too_many.actions[0].params = {"a", "b", "c", "d", "e"};
  const std::vector<double> g1(too_many.genome_size());
  EXPECT_THROW(Controller(too_many, g1), std::invalid_argument);

  ControllerSpec incomplete = tiny_symbolic();
  incomplete.actions[1].left = expr::Program{};
  const std::vector<double> g2(incomplete.genome_size());
  EXPECT_THROW(Controller(incomplete, g2), std::invalid_argument);

  ControllerSpec bad_input = tiny_classical();
  bad_input.mlp.inputs[1] = expr::kFrameSize;
  const std::vector<double> g3(bad_input.genome_size());
  EXPECT_THROW(Controller(bad_input, g3), std::invalid_argument);

  ControllerSpec empty_layer = tiny_classical();
  empty_layer.mlp.hidden = {2, 0};
  const std::vector<double> g4(empty_layer.genome_size());
  EXPECT_THROW(Controller(empty_layer, g4), std::invalid_argument);
}

TEST(Controller, RebindSwitchesGenomeAndResets) {
  const ControllerSpec spec = tiny_symbolic();
  std::vector<double> other = kSymbolicGenome;
  other[4] = 5.0;  // right wins
  Controller fresh(spec, other);
  Controller reused(spec, kSymbolicGenome);
  expr::Frame f{};
  f[expr::slot::ir] = 0.5;
  (void)reused.step(f);
  ASSERT_EQ(reused.last_action(), 1);
  reused.rebind(other);
  EXPECT_EQ(reused.last_action(), -1);
  const WheelCommand a = reused.step(f);
  const WheelCommand b = fresh.step(f);
  EXPECT_EQ(reused.last_action(), 2);
  EXPECT_EQ(a.left, b.left);
  EXPECT_EQ(a.right, b.right);
  const std::vector<double> wrong(3);
  EXPECT_THROW(reused.rebind(wrong), std::invalid_argument);
}

TEST(Controller, ResetClearsLastAction) {
  const ControllerSpec spec = tiny_symbolic();
  Controller c(spec, kSymbolicGenome);
  expr::Frame f{};
  (void)c.step(f);
  EXPECT_EQ(c.last_action(), 0);
  c.reset();
  EXPECT_EQ(c.last_action(), -1);
}

}  // namespace
}  // namespace esc::control
