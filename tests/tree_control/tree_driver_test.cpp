// tree_control::TreeDriver: a compared tree controller (a ControllerSpec with primitives) bound
// to a tree. A Behavior tree's delegates are hand-written behaviors with constant
// arguments and evolved controllers (networks or trees), each run by the driver's own actor,
// reset with it; the head and the primitives' root must agree. And an evolved tree as a
// network supervisor's frozen behavior (make_actor).
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>

#include "runtime/control/controller.hpp"
#include "runtime/genome/tree/codec.hpp"
#include "runtime/tree_control/tree_driver.hpp"
#include "tests/gp/helpers.hpp"

namespace esc::tree_control {
namespace {

using control::BehaviorCall;
using control::Controller;
using control::ControllerSpec;
using control::FixedController;
using control::Head;
using control::NetworkKind;
using control::WheelCommand;


std::shared_ptr<const ControllerSpec> elman() {
  auto net = std::make_shared<ControllerSpec>();
  net->name = "net";
  for (expr::Slot i = 0; i < expr::kIrCount; ++i) net->mlp.inputs.push_back(expr::slot::ir + i);
  net->mlp.hidden = {3};
  net->mlp.kind = NetworkKind::Elman;
  return net;
}

std::vector<double> weights(std::size_t n) {
  Rng rng(5);
  std::vector<double> w(n);
  for (double& x : w) x = rng.uniform(-1.0, 1.0);
  return w;
}

// A tree supervisor over go(0.5) and an evolved Elman network.
ControllerSpec supervisor() {
  ControllerSpec c;
  c.name = "TV";
  c.head = Head::Supervisor;
  const auto net = elman();
  c.behaviors.push_back({"go(0.5)", BehaviorCall{genome::tree::test::signed_behavior("go", 1, 1), {0.5}}});
  c.behaviors.push_back({"net", FixedController{net, weights(net->genome_size())}});
  auto p = genome::tree::test::numeric_primitives();
  p.push_back(genome::tree::prim::behavior("go(0.5)", 0));
  p.push_back(genome::tree::prim::behavior("net", 1));
  p.push_back(genome::tree::prim::if_then_else(genome::tree::Type::Behavior));
  c.primitives = std::make_shared<const genome::tree::PrimitiveSet>(std::move(p), genome::tree::Type::Behavior);
  return c;
}

std::vector<expr::Frame> frames(int n) {
  Rng rng(11);
  std::vector<expr::Frame> out;
  for (int k = 0; k < n; ++k) out.push_back(genome::tree::test::random_frame(rng));
  return out;
}

TEST(TreeDriver, AnEvolvedNetworkDelegateRunsLikeItsController) {
  const ControllerSpec spec = supervisor();
  const auto& fixed = std::get<FixedController>(spec.behaviors[1].what);
  Controller alone(*fixed.spec, fixed.genome);
  TreeDriver driver(spec, genome::tree::test::postfix(*spec.primitives, {"net"}));
  for (int round = 0; round < 2; ++round) {   // reset() clears the network's context
    driver.reset();
    alone.reset();
    for (expr::Frame f : frames(30)) {
      expr::Frame g = f;
      const WheelCommand a = driver.step(f);
      const WheelCommand b = alone.step(g);
      EXPECT_EQ(a.left, b.left);
      EXPECT_EQ(a.right, b.right);
      EXPECT_EQ(driver.last_action(), 1);
    }
  }
}

TEST(TreeDriver, AHandWrittenDelegateGetsItsArguments) {
  const ControllerSpec spec = supervisor();
  // if ir[0] > 0.5 then net else go(0.5)
  TreeDriver driver(spec, genome::tree::test::postfix(*spec.primitives, {"ir[0]", {"erc", 0.5}, ">", "net", "go(0.5)", "if"}));
  expr::Frame f{};
  f[expr::slot::ir] = 0.1;
  const WheelCommand w = driver.step(f);
  EXPECT_EQ(w.left, 0.5);
  EXPECT_EQ(w.right, 0.5);
  EXPECT_EQ(driver.last_action(), 0);
  f[expr::slot::ir] = 0.9;
  (void)driver.step(f);
  EXPECT_EQ(driver.last_action(), 1);
  EXPECT_EQ(driver.tree_spec().behaviors.size(), 2u);
}

// A Wheels tree over ir[0]: `wheels(ir[0], 0.25)`.
std::shared_ptr<const ControllerSpec> wheels_tree() {
  auto t = std::make_shared<ControllerSpec>();
  t->name = "GW";
  t->head = Head::Classical;
  auto p = genome::tree::test::numeric_primitives();
  p.push_back(genome::tree::prim::wheels());
  t->primitives = std::make_shared<const genome::tree::PrimitiveSet>(std::move(p), genome::tree::Type::Wheels);
  return t;
}

TEST(TreeDriver, AnEvolvedTreeIsAFrozenBehaviorOfANetworkSupervisor) {
  const auto tree = wheels_tree();
  const std::vector<double> genome =
      genome::tree::encode(genome::tree::test::postfix(*tree->primitives, {"ir[0]", {"erc", 0.25}, "wheels"}));
  ControllerSpec sv;
  sv.name = "SV";
  sv.head = Head::Supervisor;
  for (expr::Slot i = 0; i < expr::kIrCount; ++i) sv.mlp.inputs.push_back(expr::slot::ir + i);
  sv.behaviors.push_back({"GW", FixedController{tree, genome}});
  sv.behaviors.push_back({"go(0.5)", BehaviorCall{genome::tree::test::signed_behavior("go", 1, 1), {0.5}}});
  // Output 0 (the tree) always wins: a large bias.
  std::vector<double> w(sv.genome_size(), 0.0);
  w[0] = 5.0;
  // A network alone cannot build a tree; the factory of tree_control can.
  EXPECT_THROW(Controller(sv, w), std::invalid_argument);
  Controller c(sv, w, &make_actor);
  for (expr::Frame f : frames(20)) {
    const WheelCommand cmd = c.step(f);
    EXPECT_EQ(cmd.left, std::clamp(f[expr::slot::ir], -1.0, 1.0));   // wheel commands are clamped
    EXPECT_EQ(cmd.right, 0.25);
    EXPECT_EQ(c.last_action(), 0);
  }
  EXPECT_EQ(c.usage()[0], 20);
  ASSERT_NE(c.sub_controller(0), nullptr);
  EXPECT_EQ(c.sub_controller(0)->last_action(), -1);   // a Wheels tree chooses nothing
}

TEST(TreeDriver, AnEvolvedTreeIsADelegateOfATreeSupervisor) {
  ControllerSpec spec = supervisor();
  const auto tree = wheels_tree();
  spec.behaviors[1] = {"GW", FixedController{tree, genome::tree::encode(genome::tree::test::postfix(*tree->primitives,
                                                                                {"ir[1]", {"erc", -0.5}, "wheels"}))}};
  TreeDriver driver(spec, genome::tree::test::postfix(*spec.primitives, {"net"}));   // behavior 1, now the tree
  for (expr::Frame f : frames(10)) {
    const WheelCommand cmd = driver.step(f);
    EXPECT_EQ(cmd.left, std::clamp(f[expr::slot::ir + 1], -1.0, 1.0));   // wheel commands are clamped
    EXPECT_EQ(cmd.right, -0.5);
  }
  EXPECT_EQ(driver.usage()[1], 10);
  EXPECT_EQ(driver.usage()[0], 0);
  driver.clear_usage();
  EXPECT_EQ(driver.usage()[1], 0);
}

TEST(TreeDriver, TheHeadMustMatchThePrimitives) {
  ControllerSpec spec = supervisor();
  const genome::tree::Tree tree = genome::tree::test::postfix(*spec.primitives, {"net"});
  spec.head = Head::Classical;
  EXPECT_THROW(TreeDriver(spec, tree), std::invalid_argument);
  ControllerSpec network = *elman();
  EXPECT_THROW(TreeDriver(network, tree), std::invalid_argument);
  // A tree spec is not a network: Controller refuses it.
  EXPECT_THROW(Controller(supervisor(), {}), std::invalid_argument);
}

}  // namespace
}  // namespace esc::tree_control
