// Elman networks: one hidden layer fully connected to itself with a one-step delay.
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "runtime/control/controller.hpp"
#include "tests/control/behaviors.hpp"

namespace esc::control {
namespace {

using namespace testing;  // NOLINT

// Two IR inputs, two recurrent hidden neurons, classical head: 2*(1+2+2) + 2*(1+2) = 16.
ControllerSpec tiny_elman() {
  ControllerSpec s;
  s.name = "tiny_elman";
  s.mlp.inputs = {expr::slot::ir, expr::slot::ir + 1};
  s.mlp.hidden = {2};
  s.mlp.kind = NetworkKind::Elman;
  return s;
}

// Hidden neuron by neuron: bias, 2 input weights, 2 context weights; then each output:
// bias, 2 hidden weights.
const std::vector<double> kElmanGenome = {
    0.1,  0.5,  -0.3, 0.9,  -0.6,  // hidden 0
    -0.2, 0.4,  0.8,  0.3,  0.7,   // hidden 1
    0.05, 1.0,  -0.5,              // output 0 (left)
    -0.1, 0.3,  0.7,               // output 1 (right)
};

struct Reference {
  double h0 = 0.0, h1 = 0.0;  // context: previous hidden activations
  WheelCommand step(double x0, double x1) {
    const double n0 = std::tanh(0.1 + 0.5 * x0 - 0.3 * x1 + 0.9 * h0 - 0.6 * h1);
    const double n1 = std::tanh(-0.2 + 0.4 * x0 + 0.8 * x1 + 0.3 * h0 + 0.7 * h1);
    h0 = n0;
    h1 = n1;
    return {std::tanh(0.05 + 1.0 * n0 - 0.5 * n1), std::tanh(-0.1 + 0.3 * n0 + 0.7 * n1)};
  }
};

WheelCommand step_with(Controller& c, double x0, double x1) {
  expr::Frame f{};
  f[expr::slot::ir] = x0;
  f[expr::slot::ir + 1] = x1;
  return c.step(f);
}

const double kInputs[3][2] = {{0.6, 0.2}, {-0.4, 0.9}, {0.1, -0.7}};

TEST(Elman, MatchesHandComputationOverThreeSteps) {
  const ControllerSpec spec = tiny_elman();
  ASSERT_EQ(spec.genome_size(), kElmanGenome.size());
  Controller c(spec, kElmanGenome);
  Reference ref;
  for (const auto& x : kInputs) {
    const WheelCommand w = step_with(c, x[0], x[1]);
    const WheelCommand r = ref.step(x[0], x[1]);
    EXPECT_NEAR(w.left, r.left, 1e-14);
    EXPECT_NEAR(w.right, r.right, 1e-14);
  }
}

TEST(Elman, OutputDependsOnThePreviousStep) {
  const ControllerSpec spec = tiny_elman();
  Controller a(spec, kElmanGenome);
  Controller b(spec, kElmanGenome);
  (void)step_with(a, 0.6, 0.2);
  (void)step_with(b, -0.8, 0.5);
  const WheelCommand wa = step_with(a, 0.1, 0.1);  // same input now, different history
  const WheelCommand wb = step_with(b, 0.1, 0.1);
  EXPECT_NE(wa.left, wb.left);
  EXPECT_NE(wa.right, wb.right);

  // The same net without recurrence (context weights zero) forgets the history.
  std::vector<double> g = kElmanGenome;
  for (std::size_t i : {3u, 4u, 8u, 9u}) g[i] = 0.0;
  Controller fa(spec, g);
  Controller fb(spec, g);
  (void)step_with(fa, 0.6, 0.2);
  (void)step_with(fb, -0.8, 0.5);
  const WheelCommand ga = step_with(fa, 0.1, 0.1);
  const WheelCommand gb = step_with(fb, 0.1, 0.1);
  EXPECT_EQ(ga.left, gb.left);
  EXPECT_EQ(ga.right, gb.right);
}

TEST(Elman, FirstStepSeesAZeroContext) {
  // At the first step the context is zero: equal to an MLP with the context weights dropped.
  ControllerSpec mlp = tiny_elman();
  mlp.mlp.kind = NetworkKind::Mlp;
  const std::vector<double> g_mlp = {0.1,  0.5, -0.3, -0.2, 0.4, 0.8,
                                     0.05, 1.0, -0.5, -0.1, 0.3, 0.7};
  const ControllerSpec elman = tiny_elman();
  Controller e(elman, kElmanGenome);
  Controller m(mlp, g_mlp);
  const WheelCommand we = step_with(e, 0.6, 0.2);
  const WheelCommand wm = step_with(m, 0.6, 0.2);
  EXPECT_DOUBLE_EQ(we.left, wm.left);  // equal up to summation order
  EXPECT_DOUBLE_EQ(we.right, wm.right);
}

TEST(Elman, ResetClearsTheContext) {
  const ControllerSpec spec = tiny_elman();
  Controller used(spec, kElmanGenome);
  for (int k = 0; k < 5; ++k) (void)step_with(used, 0.3 * k, -0.2 * k);
  used.reset();
  Controller fresh(spec, kElmanGenome);
  for (const auto& x : kInputs) {
    const WheelCommand a = step_with(used, x[0], x[1]);
    const WheelCommand b = step_with(fresh, x[0], x[1]);
    EXPECT_EQ(a.left, b.left);
    EXPECT_EQ(a.right, b.right);
  }
}

TEST(Elman, RebindResetsTheContext) {
  const ControllerSpec spec = tiny_elman();
  std::vector<double> other = kElmanGenome;
  other[0] = -0.4;
  Controller used(spec, kElmanGenome);
  (void)step_with(used, 0.9, 0.9);
  used.rebind(other);
  Controller fresh(spec, other);
  const WheelCommand a = step_with(used, 0.2, 0.4);
  const WheelCommand b = step_with(fresh, 0.2, 0.4);
  EXPECT_EQ(a.left, b.left);
  EXPECT_EQ(a.right, b.right);
}

TEST(Elman, SymbolicHeadOnAnElmanNetwork) {
  ControllerSpec s;
  s.mlp.inputs = {expr::slot::ir};
  s.mlp.hidden = {1};
  s.mlp.kind = NetworkKind::Elman;
  s.head = Head::Symbolic;
  s.actions = {forward(), left()};
  // Hidden h_t = tanh(x_t + 2 h_{t-1}); choosers: forward -h, left +h; params constant.
  const std::vector<double> g = {0.0, 1.0, 2.0,  // hidden: bias, input, context
                                 0.0, -1.0, 0.0, 1.0, 2.0, 0.0, -2.0, 0.0};
  ASSERT_EQ(s.genome_size(), g.size());
  Controller c(s, g);
  expr::Frame f{};
  f[expr::slot::ir] = 0.5;  // h = tanh(0.5) > 0: left
  (void)c.step(f);
  EXPECT_EQ(c.last_action(), 1);
  f[expr::slot::ir] = -0.5;  // h = tanh(-0.5 + 2 tanh(0.5)) > 0: still left, by memory
  (void)c.step(f);
  EXPECT_EQ(c.last_action(), 1);
  c.reset();
  (void)c.step(f);  // h = tanh(-0.5) < 0: forward
  EXPECT_EQ(c.last_action(), 0);
}

TEST(Elman, PaperGenomeSizes) {
  ControllerSpec cc;
  cc.mlp.inputs = seventeen_inputs();
  cc.mlp.hidden = {5};
  cc.mlp.kind = NetworkKind::Elman;
  EXPECT_EQ(cc.genome_size(), 127u);  // 5 * (1 + 17 + 5) + 2 * (1 + 5)
  EXPECT_EQ(cc.architecture(), "17-5r-2");

  ControllerSpec sc = cc;
  sc.head = Head::Symbolic;
  sc.actions = {forward(), left(), right()};
  EXPECT_EQ(sc.output_count(), 6);
  EXPECT_EQ(sc.genome_size(), 5u * 23u + 6u * 6u);  // 151
  EXPECT_EQ(sc.architecture(), "17-5r-6");

  ControllerSpec sup = cc;
  sup.head = Head::Supervisor;
  for (const char* n : {"avoid", "light", "sweep", "stop"})
    sup.behaviors.push_back({n, BehaviorCall{stop(), {}}});
  EXPECT_EQ(sup.output_count(), 4);
  EXPECT_EQ(sup.genome_size(), 5u * 23u + 4u * 6u);  // 139
  EXPECT_EQ(sup.architecture(), "17-5r-4");

  const std::vector<double> g127(127);
  EXPECT_NO_THROW(Controller(cc, g127));
}

TEST(Elman, NeedsExactlyOneHiddenLayer) {
  ControllerSpec none = tiny_elman();
  none.mlp.hidden = {};
  const std::vector<double> g0(none.genome_size());
  EXPECT_THROW(Controller(none, g0), std::invalid_argument);

  ControllerSpec two = tiny_elman();
  two.mlp.hidden = {2, 2};
  const std::vector<double> g2(two.genome_size());
  try {
    Controller c(two, g2);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("tiny_elman"), std::string::npos) << msg;
    EXPECT_NE(msg.find("Elman"), std::string::npos) << msg;
  }

  ControllerSpec empty = tiny_elman();
  empty.mlp.hidden = {0};
  const std::vector<double> ge(empty.genome_size());
  EXPECT_THROW(Controller(empty, ge), std::invalid_argument);

  const std::vector<double> short_genome(15);
  EXPECT_THROW(Controller(tiny_elman(), short_genome), std::invalid_argument);
}

}  // namespace
}  // namespace esc::control
