// Trees as doubles (codec.hpp), and Action trees inlined into Wheels trees
// (inline_actions.hpp): both exact, and bad input refused.
#include <gtest/gtest.h>

#include "runtime/control/tree_controller.hpp"
#include "runtime/evo/gp/codec.hpp"
#include "runtime/evo/gp/init.hpp"
#include "runtime/evo/gp/inline_actions.hpp"
#include "runtime/evo/gp/program.hpp"
#include "tests/gp/helpers.hpp"

namespace esc::evo::gp {
namespace {

TEST(Codec, EveryTreeOfEveryRootRoundTrips) {
  Rng rng(17);
  for (const PrimitiveSet& set : test::all_sets()) {
    for (int i = 0; i < 50; ++i) {
      const Tree t = i % 2 == 0 ? full(set, set.root(), 1 + i % 6, rng) : grow(set, set.root(), 8, rng);
      const std::vector<double> genes = encode(t);
      EXPECT_EQ(genes.size(), kCodedNodeWidth * t.size());
      EXPECT_EQ(decode(genes, set), t);
    }
  }
}

TEST(Codec, WhatIsNotATreeOfTheSetIsRefused) {
  const PrimitiveSet set = test::wheels_set();
  Rng rng(3);
  const std::vector<double> genes = encode(full(set, Type::Wheels, 3, rng));
  EXPECT_THROW((void)decode({}, set), std::invalid_argument);
  EXPECT_THROW((void)decode(std::span(genes).first(genes.size() - 1), set), std::invalid_argument);
  EXPECT_THROW((void)decode(std::span(genes).first(genes.size() - 2), set), std::invalid_argument);   // no root
  std::vector<double> bad = genes;
  bad[0] = static_cast<double>(set.size());
  EXPECT_THROW((void)decode(bad, set), std::invalid_argument);
  bad[0] = 0.5;
  EXPECT_THROW((void)decode(bad, set), std::invalid_argument);
  EXPECT_THROW((void)decode(genes, test::number_set()), std::invalid_argument);   // another root
}

TEST(InlineActions, TheInlinedTreeGivesTheActionTreesCommands) {
  const PrimitiveSet set = test::action_set();
  const std::vector<control::Behavior> actions = test::standard_actions();
  const control::TreeControllerSpec spec{"a", set, actions, {}};
  Rng rng(23);
  for (int i = 0; i < 40; ++i) {
    const Tree t = i % 2 == 0 ? full(set, Type::Action, 2 + i % 5, rng) : grow(set, Type::Action, 8, rng);
    const InlinedTree in = inline_actions(t, set, actions);
    EXPECT_EQ(in.set.root(), Type::Wheels);
    const control::TreeControllerSpec wheels{"w", in.set, actions, {}};   // the old actions stay in the set
    control::TreeController a(spec, t);
    control::TreeController w(wheels, in.tree);
    for (int f = 0; f < 50; ++f) {
      expr::Frame x = test::random_frame(rng);
      expr::Frame y = x;
      const control::WheelCommand ca = a.step(x);
      const control::WheelCommand cw = w.step(y);
      ASSERT_EQ(ca.left, cw.left) << i;
      ASSERT_EQ(ca.right, cw.right) << i;
    }
  }
}

TEST(InlineActions, OnlyActionTreesWithTheirBehaviors) {
  Rng rng(2);
  const PrimitiveSet set = test::action_set();
  const Tree t = full(set, Type::Action, 3, rng);
  std::vector<control::Behavior> actions = test::standard_actions();
  EXPECT_THROW((void)inline_actions(t, test::wheels_set(), actions), std::invalid_argument);
  actions.pop_back();   // `stop` has no behavior
  EXPECT_THROW((void)inline_actions(test::postfix(set, {"stop"}), set, actions), std::invalid_argument);
  // A behavior reading `in(zone)`: no name of its own in scripts.
  control::Behavior zone = test::standard_actions().back();
  zone.left = expr::Program();
  zone.left.push_load(expr::slot::in_zone);
  actions = test::standard_actions();
  actions.back() = zone;
  EXPECT_THROW((void)inline_actions(test::postfix(set, {"stop"}), set, actions), std::invalid_argument);
}

}  // namespace
}  // namespace esc::evo::gp
