// TreeController::step and FlatProgram::run must not allocate (allocations counted by
// tests/support/allocation_counter.hpp).
#include <atomic>
#include <cstdlib>
#include <new>

#include <gtest/gtest.h>

#include "runtime/control/tree_controller.hpp"
#include "runtime/evo/gp/init.hpp"
#include "tests/gp/helpers.hpp"
#include "tests/support/allocation_counter.hpp"


namespace esc::control {
namespace {

namespace gp = evo::gp;

TEST(NoAlloc, TreeControllerStepDoesNotAllocate) {
  std::vector<Delegate> delegates(3);
  for (std::size_t k = 0; k < 3; ++k) delegates[k].behavior = gp::test::signed_behavior("b", 1, -1);
  const std::vector<TreeControllerSpec> specs = {
      {"w", gp::test::wheels_set(), {}, {}},
      {"a", gp::test::action_set(), gp::test::standard_actions(), {}},
      {"s", gp::test::behavior_set(), {}, delegates}};
  for (const TreeControllerSpec& spec : specs) {
    Rng rng(7);
    std::vector<TreeController> ctls;
    for (int k = 0; k < 20; ++k)
      ctls.emplace_back(spec, gp::full(spec.primitives, spec.primitives.root(), 6, rng));
    std::vector<expr::Frame> frames;
    for (int k = 0; k < 50; ++k) frames.push_back(gp::test::random_frame(rng));
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

}  // namespace
}  // namespace esc::control
