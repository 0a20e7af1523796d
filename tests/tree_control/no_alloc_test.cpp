// TreeController::step and FlatProgram::run must not allocate (allocations counted by
// tests/support/allocation_counter.hpp).
#include <atomic>
#include <cstdlib>
#include <new>

#include <gtest/gtest.h>

#include "runtime/genome/tree/init.hpp"
#include "runtime/tree_control/tree_controller.hpp"
#include "runtime/tree_control/tree_driver.hpp"
#include "tests/gp/helpers.hpp"
#include "tests/support/allocation_counter.hpp"


namespace esc::tree_control {
namespace {

using control::BehaviorCall;
using control::ControllerSpec;
using control::FixedController;
using control::Head;
using control::NetworkKind;
using control::WheelCommand;


TEST(NoAlloc, TreeControllerStepDoesNotAllocate) {
  std::vector<Delegate> delegates(3);
  for (std::size_t k = 0; k < 3; ++k) delegates[k].behavior = genome::tree::test::signed_behavior("b", 1, -1);
  const std::vector<TreeControllerSpec> specs = {
      {"w", genome::tree::test::wheels_set(), {}, {}},
      {"a", genome::tree::test::action_set(), genome::tree::test::standard_actions(), {}},
      {"s", genome::tree::test::behavior_set(), {}, delegates}};
  for (const TreeControllerSpec& spec : specs) {
    Rng rng(7);
    std::vector<TreeController> ctls;
    for (int k = 0; k < 20; ++k)
      ctls.emplace_back(spec, genome::tree::full(spec.primitives, spec.primitives.root(), 6, rng));
    std::vector<expr::Frame> frames;
    for (int k = 0; k < 50; ++k) frames.push_back(genome::tree::test::random_frame(rng));
    double sum = 0.0;
    g_news = 0;
    g_counting = true;
    for (TreeController& c : ctls) {
      c.reset();
      for (expr::Frame& f : frames) {
        const WheelCommand w = c.step(f);
        sum += w.left + w.right;
      }
    }
    g_counting = false;
    EXPECT_EQ(g_news.load(), 0) << spec.name;
    EXPECT_TRUE(std::isfinite(sum));
  }
}

TEST(NoAlloc, TreeDriverOverAnEvolvedNetworkDoesNotAllocate) {
  auto net = std::make_shared<ControllerSpec>();
  for (expr::Slot i = 0; i < expr::kIrCount; ++i) net->mlp.inputs.push_back(expr::slot::ir + i);
  net->mlp.hidden = {4};
  net->mlp.kind = NetworkKind::Elman;
  ControllerSpec spec;
  spec.name = "tv";
  spec.head = Head::Supervisor;
  spec.behaviors.push_back({"go", BehaviorCall{genome::tree::test::signed_behavior("go", 1, 1), {0.5}}});
  spec.behaviors.push_back({"net", FixedController{net, std::vector<double>(net->genome_size(), 0.1)}});
  auto p = genome::tree::test::numeric_primitives();
  p.push_back(genome::tree::prim::behavior("go", 0));
  p.push_back(genome::tree::prim::behavior("net", 1));
  p.push_back(genome::tree::prim::if_then_else(genome::tree::Type::Behavior));
  spec.primitives = std::make_shared<const genome::tree::PrimitiveSet>(std::move(p), genome::tree::Type::Behavior);
  Rng rng(3);
  std::vector<expr::Frame> frames;
  for (int k = 0; k < 50; ++k) frames.push_back(genome::tree::test::random_frame(rng));
  double sum = 0.0;
  for (int k = 0; k < 10; ++k) {
    TreeDriver driver(spec, genome::tree::full(*spec.primitives, genome::tree::Type::Behavior, 5, rng));
    g_news = 0;
    g_counting = true;
    driver.reset();
    for (expr::Frame& f : frames) sum += driver.step(f).left;
    g_counting = false;
    EXPECT_EQ(g_news.load(), 0);
  }
  EXPECT_TRUE(std::isfinite(sum));
}

}  // namespace
}  // namespace esc::tree_control
