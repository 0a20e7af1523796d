// TreeController: the three uses of a tree, spec checks, and the round trip of a Wheels
// tree through the behavior the printed script compiles to.
#include <bit>

#include <gtest/gtest.h>

#include "runtime/genome/tree/init.hpp"
#include "runtime/tree_control/tree_behavior.hpp"
#include "runtime/tree_control/tree_controller.hpp"
#include "tests/gp/helpers.hpp"

namespace esc::tree_control {
namespace {

using control::Behavior;
using control::WheelCommand;
using genome::tree::PrimitiveSet;
using genome::tree::Tree;
using genome::tree::Type;
using genome::tree::test::postfix;

TEST(TreeController, WheelsTreeGivesTheWheelCommands) {
  const TreeControllerSpec spec{"w", genome::tree::test::wheels_set(), {}, {}};
  // wheels(ir[0] * 2, -0.5)
  TreeController c(spec, postfix(spec.primitives, {"ir[0]", {"erc", 2.0}, "*", {"erc", -0.5}, "wheels"}));
  expr::Frame f{};
  f[expr::slot::ir] = 0.2;
  WheelCommand w = c.step(f);
  EXPECT_EQ(w.left, 0.4);
  EXPECT_EQ(w.right, -0.5);
  EXPECT_EQ(c.last_action(), -1);
  f[expr::slot::ir] = 0.9;  // 1.8 is clamped like a behavior's wheel command
  EXPECT_EQ(c.step(f).left, 1.0);
}

TEST(TreeController, ActionTreePicksTheActionAndPassesItsParameter) {
  const TreeControllerSpec spec{"a", genome::tree::test::action_set(), genome::tree::test::standard_actions(), {}};
  // if ir[1] > 0.5 then left(ir[1]) else forward(0.25)
  TreeController c(spec, postfix(spec.primitives, {"ir[1]", {"erc", 0.5}, ">", "ir[1]", "left",
                                                   {"erc", 0.25}, "forward", "if"}));
  expr::Frame f{};
  f[expr::slot::ir + 1] = 0.9;
  WheelCommand w = c.step(f);
  EXPECT_EQ(c.last_action(), 1);
  EXPECT_EQ(f[expr::slot::param], 0.9);
  EXPECT_EQ(w.left, -0.9);
  EXPECT_EQ(w.right, 0.9);
  f[expr::slot::ir + 1] = 0.1;
  w = c.step(f);
  EXPECT_EQ(c.last_action(), 0);
  EXPECT_EQ(f[expr::slot::param], 0.25);
  EXPECT_EQ(w.left, 0.25);
  EXPECT_EQ(w.right, 0.25);
  c.rebind(postfix(spec.primitives, {"stop"}));
  EXPECT_EQ(c.last_action(), -1);
  w = c.step(f);
  EXPECT_EQ(c.last_action(), 4);
  EXPECT_EQ(w.left, 0.0);
}

TEST(TreeController, SupervisorDelegatesToBehaviorsAndControllers) {
  int calls = 0, resets = 0;
  std::vector<Delegate> delegates(3);
  delegates[0].name = "avoid";
  delegates[0].behavior = genome::tree::test::signed_behavior("right", 1, -1);
  delegates[0].params = {0.7, 0, 0, 0};
  delegates[1].name = "explore";
  delegates[1].behavior = genome::tree::test::signed_behavior("forward", 1, 1);
  delegates[1].params = {0.4, 0, 0, 0};
  delegates[2].name = "home";  // any controller, through the hook
  delegates[2].step = [&calls](expr::Frame&) {
    ++calls;
    return WheelCommand{0.1, 0.2};
  };
  delegates[2].reset = [&resets] { ++resets; };
  const TreeControllerSpec spec{"s", genome::tree::test::behavior_set(), {}, delegates};
  // if collision then avoid else if ir[0] < 0.2 then explore else home
  TreeController c(spec, postfix(spec.primitives, {"collision", "avoid", "ir[0]", {"erc", 0.2}, "<",
                                                   "explore", "home", "if", "if"}));
  EXPECT_EQ(resets, 0);
  expr::Frame f{};
  f[expr::slot::collision] = 1.0;
  WheelCommand w = c.step(f);
  EXPECT_EQ(c.last_action(), 0);
  EXPECT_EQ(w.left, 0.7);
  EXPECT_EQ(w.right, -0.7);
  f[expr::slot::collision] = 0.0;
  w = c.step(f);
  EXPECT_EQ(c.last_action(), 1);
  EXPECT_EQ(w.left, 0.4);
  f[expr::slot::ir] = 0.5;
  w = c.step(f);
  EXPECT_EQ(c.last_action(), 2);
  EXPECT_EQ(w.right, 0.2);
  EXPECT_EQ(calls, 1);
  c.reset();
  EXPECT_EQ(resets, 1);
  EXPECT_EQ(c.last_action(), -1);
}

TEST(TreeController, RejectsSpecsItCannotRun) {
  const auto error = [](const TreeControllerSpec& spec, const Tree& t) -> std::string {
    try {
      TreeController c(spec, t);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "";
  };
  const PrimitiveSet a = genome::tree::test::action_set();
  auto too_few = genome::tree::test::standard_actions();
  too_few.pop_back();
  const Tree stop = postfix(a, {"stop"});
  EXPECT_NE(error({"a", a, too_few, {}}, stop).find("action `stop` has index 4, but there are 4 actions"),
            std::string::npos);
  auto mismatch = genome::tree::test::standard_actions();
  mismatch[4].params = {"p"};
  EXPECT_NE(error({"a", a, mismatch, {}}, stop).find("passes 0 parameters, but behavior 'stop' takes 1"),
            std::string::npos);
  const PrimitiveSet n = genome::tree::test::number_set();
  EXPECT_NE(error({"n", n, {}, {}}, postfix(n, {"ir[0]"})).find("root type"), std::string::npos);
  const PrimitiveSet w = genome::tree::test::wheels_set();
  Tree bad = postfix(w, {"ir[0]", "ir[1]", "wheels"});
  bad.nodes[0].length = 3;
  EXPECT_NE(error({"w", w, {}, {}}, bad).find("ill-typed tree"), std::string::npos);
  EXPECT_NE(error({"b", genome::tree::test::behavior_set(), {}, {}}, postfix(genome::tree::test::behavior_set(), {"avoid"}))
                .find("there are 0 behaviors"),
            std::string::npos);
}

// The printed behavior (to_behavior is what the compiler makes of behavior_script's text)
// drives the robot exactly like the tree: same commands bit for bit, hence same fitness.
TEST(TreeController, WheelsTreeAndItsPrintedBehaviorAgreeBitForBit) {
  const TreeControllerSpec spec{"w", genome::tree::test::wheels_set(), {}, {}};
  for (std::uint64_t seed = 0; seed < 1000; ++seed) {
    Rng rng(seed, {41});
    const Tree t = genome::tree::grow(spec.primitives, Type::Wheels, 2 + static_cast<int>(seed % 7), rng);
    TreeController c(spec, t);
    const Behavior b = to_behavior(t, spec.primitives, "evolved");
    for (int k = 0; k < 8; ++k) {
      expr::Frame f = genome::tree::test::random_frame(rng);
      const WheelCommand want = run_behavior(b, f);
      const WheelCommand got = c.step(f);
      ASSERT_EQ(std::bit_cast<std::uint64_t>(got.left), std::bit_cast<std::uint64_t>(want.left)) << seed;
      ASSERT_EQ(std::bit_cast<std::uint64_t>(got.right), std::bit_cast<std::uint64_t>(want.right)) << seed;
    }
  }
}

}  // namespace
}  // namespace esc::tree_control
