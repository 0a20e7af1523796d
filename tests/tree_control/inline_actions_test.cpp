// Action trees inlined into Wheels trees (inline_actions.hpp): the inlined tree gives the
// Action tree's wheel commands bit for bit, and what is not an Action tree with its
// behaviors is refused.
#include <gtest/gtest.h>

#include "runtime/genome/tree/init.hpp"
#include "runtime/tree_control/inline_actions.hpp"
#include "runtime/tree_control/tree_controller.hpp"
#include "tests/gp/helpers.hpp"

namespace esc::tree_control {
namespace {

using genome::tree::PrimitiveSet;
using genome::tree::Tree;
using genome::tree::Type;

TEST(InlineActions, TheInlinedTreeGivesTheActionTreesCommands) {
  const PrimitiveSet set = genome::tree::test::action_set();
  const std::vector<control::Behavior> actions = genome::tree::test::standard_actions();
  const TreeControllerSpec spec{"a", set, actions, {}};
  Rng rng(23);
  for (int i = 0; i < 40; ++i) {
    const Tree t = i % 2 == 0 ? genome::tree::full(set, Type::Action, 2 + i % 5, rng) : genome::tree::grow(set, Type::Action, 8, rng);
    const InlinedTree in = inline_actions(t, set, actions);
    EXPECT_EQ(in.set.root(), Type::Wheels);
    const TreeControllerSpec wheels{"w", in.set, actions, {}};   // the old actions stay in the set
    TreeController a(spec, t);
    TreeController w(wheels, in.tree);
    for (int f = 0; f < 50; ++f) {
      expr::Frame x = genome::tree::test::random_frame(rng);
      expr::Frame y = x;
      const control::WheelCommand ca = a.step(x);
      const control::WheelCommand cw = w.step(y);
      ASSERT_EQ(ca.left, cw.left) << i;
      ASSERT_EQ(ca.right, cw.right) << i;
    }
  }
}

// The navigator's observables follow the behavior parameters in the frame: a behavior that
// reads `x` reads the observable, not a parameter.
TEST(InlineActions, ObservablesAfterTheParametersAreObservables) {
  const PrimitiveSet set = genome::tree::test::action_set();
  std::vector<control::Behavior> actions = genome::tree::test::standard_actions();
  actions.back().left = expr::Program();
  actions.back().left.push_load(expr::slot::x);
  const Tree t = genome::tree::test::postfix(set, {"stop"});
  const InlinedTree in = inline_actions(t, set, actions);
  const TreeControllerSpec spec{"a", set, actions, {}};
  const TreeControllerSpec wheels{"w", in.set, actions, {}};
  TreeController a(spec, t);
  TreeController w(wheels, in.tree);
  expr::Frame f{};
  f[expr::slot::x] = 0.25;
  expr::Frame g = f;
  EXPECT_EQ(a.step(f).left, 0.25);
  EXPECT_EQ(w.step(g).left, 0.25);
}

TEST(InlineActions, OnlyActionTreesWithTheirBehaviors) {
  Rng rng(2);
  const PrimitiveSet set = genome::tree::test::action_set();
  const Tree t = genome::tree::full(set, Type::Action, 3, rng);
  std::vector<control::Behavior> actions = genome::tree::test::standard_actions();
  EXPECT_THROW((void)inline_actions(t, genome::tree::test::wheels_set(), actions), std::invalid_argument);
  actions.pop_back();   // `stop` has no behavior
  EXPECT_THROW((void)inline_actions(genome::tree::test::postfix(set, {"stop"}), set, actions), std::invalid_argument);
  // A behavior reading `in(zone)`: no name of its own in scripts.
  control::Behavior zone = genome::tree::test::standard_actions().back();
  zone.left = expr::Program();
  zone.left.push_load(expr::slot::in_zone);
  actions = genome::tree::test::standard_actions();
  actions.back() = zone;
  EXPECT_THROW((void)inline_actions(genome::tree::test::postfix(set, {"stop"}), set, actions), std::invalid_argument);
}

}  // namespace
}  // namespace esc::tree_control
