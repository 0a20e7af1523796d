// Controller::step must not allocate (allocations counted by tests/support/allocation_counter.hpp).
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <new>
#include <vector>

#include <Eigen/Core>
#include <gtest/gtest.h>

#include "runtime/control/controller.hpp"
#include "tests/control/behaviors.hpp"
#include "runtime/genome/graph/codec.hpp"
#include "runtime/genome/graph/graph.hpp"
#include "tests/support/allocation_counter.hpp"


namespace esc::control {
namespace {

using namespace testing;  // NOLINT

struct CountScope {
  CountScope() {
    g_news = 0;
    g_mallocs = 0;
    g_counting = true;
  }
  ~CountScope() { g_counting = false; }
};

void fill_ir(expr::Frame& f, int t) {
  for (expr::Slot i = 0; i < expr::kIrCount; ++i)
    f[expr::slot::ir + i] = 0.5 + 0.5 * std::sin(0.37 * t + 1.3 * i);
}

std::vector<double> genome_for(const ControllerSpec& s) {
  std::vector<double> g(s.genome_size());
  for (std::size_t i = 0; i < g.size(); ++i) g[i] = std::sin(static_cast<double>(i) * 2.3);
  return g;
}

// Steps `c` `steps` times over varying IR readings, `between(t, frame)` before each step
// (resets, rebinds, other inputs), and checks that nothing was allocated in between; also
// `after()`, inside the counted scope; the wheel commands must stay finite.
template <typename Between, typename After>
void expect_no_allocation(Controller& c, int steps, Between between, After after) {
  expr::Frame f{};
  double sum = 0.0;
  {
    CountScope scope;
    for (int t = 0; t < steps; ++t) {
      fill_ir(f, t);
      between(t, f);
      const WheelCommand w = c.step(f);
      sum += w.left - w.right;
    }
    after();
  }
  EXPECT_EQ(g_news.load(), 0);
  EXPECT_EQ(g_mallocs.load(), 0);
  EXPECT_TRUE(std::isfinite(sum));
}

TEST(NoAlloc, CounterSeesAllocations) {
  long news = 0;
  {
    CountScope scope;
    auto* p = new std::vector<double>(100);
    delete p;
    news = g_news;
  }
  EXPECT_GE(news, 1);
#if defined(__GLIBC__)
  {
    CountScope scope;
    void* volatile p = std::malloc(64);
    std::free(p);
  }
  EXPECT_GE(g_mallocs.load(), 1);
  {
    CountScope scope;
    Eigen::VectorXd v = Eigen::VectorXd::Ones(100);  // Eigen allocates with malloc
    EXPECT_EQ(v.sum(), 100.0);
  }
  EXPECT_GE(g_mallocs.load(), 1);
#endif
}

TEST(NoAlloc, SymbolicStepDoesNotAllocate) {
  ControllerSpec s;
  s.mlp.inputs = ir_inputs();
  s.mlp.hidden = {14};
  s.head = Head::Symbolic;
  s.actions = {forward(), left(), right(), backward()};
  const std::vector<double> g = genome_for(s);
  Controller c(s, g);
  expect_no_allocation(c, 1000, [](int, expr::Frame&) {}, [&] { c.reset(); });
}

// A NEAT network (its graph genome grown by a split and a recurrent link) steps and resets
// without allocating; only building or rebinding it does.
TEST(NoAlloc, NeatStepDoesNotAllocate) {
  ControllerSpec s;
  s.mlp.inputs = ir_inputs();
  s.mlp.kind = NetworkKind::Graph;
  s.head = Head::Symbolic;
  s.actions = {forward(), left(), right()};
  namespace gg = genome::graph;
  gg::Graph graph = gg::minimal_graph(s.mlp.inputs.size(), static_cast<std::size_t>(s.output_count()),
                                      gg::Activation::Sigmoid);
  for (std::size_t i = 0; i < graph.links.size(); ++i) graph.links[i].weight = std::sin(static_cast<double>(i) * 2.3);
  const gg::Id hidden = gg::next_node_id(graph);
  const gg::Id out = graph.nodes.back().id;
  gg::Id innovation = gg::next_innovation(graph);
  gg::insert_node(graph, {hidden, gg::NodeKind::Hidden, gg::Activation::NeatSigmoid});
  gg::insert_link(graph, {1, hidden, 0.8, true, innovation++});
  gg::insert_link(graph, {hidden, out, -1.2, true, innovation++});
  gg::insert_link(graph, {out, hidden, 0.4, true, innovation++});
  const std::vector<double> g = gg::encode(graph);
  Controller c(s, g);
  expect_no_allocation(
      c, 1000,
      [&](int t, expr::Frame&) {
        if (t % 150 == 0) c.reset();
      },
      [&] { c.reset(); });
}

TEST(NoAlloc, ClassicalStepDoesNotAllocate) {
  ControllerSpec s;
  s.mlp.inputs = ir_inputs();
  s.mlp.hidden = {20, 7};
  const std::vector<double> g = genome_for(s);
  const std::vector<double> g2(g.rbegin(), g.rend());
  Controller c(s, g);
  expect_no_allocation(
      c, 1000,
      [&](int t, expr::Frame&) {
        if (t == 500) c.rebind(g2);  // rebinding reuses the buffers
      },
      [] {});
}

TEST(NoAlloc, ElmanStepDoesNotAllocate) {
  ControllerSpec s;
  s.mlp.inputs = seventeen_inputs();
  s.mlp.hidden = {5};
  s.mlp.kind = NetworkKind::Elman;
  s.head = Head::Symbolic;
  s.actions = {forward(), left(), right()};
  const std::vector<double> g = genome_for(s);
  Controller c(s, g);
  expect_no_allocation(
      c, 1000,
      [&](int t, expr::Frame&) {
        if (t % 250 == 0) c.reset();
      },
      [] {});
}

TEST(NoAlloc, SupervisorOverElmanSubControllersDoesNotAllocate) {
  auto classical = std::make_shared<ControllerSpec>();
  classical->mlp.inputs = seventeen_inputs();
  classical->mlp.hidden = {5};
  classical->mlp.kind = NetworkKind::Elman;
  auto symbolic = std::make_shared<ControllerSpec>(*classical);
  symbolic->head = Head::Symbolic;
  symbolic->actions = {forward(), left(), right()};

  ControllerSpec s;
  s.mlp = classical->mlp;  // Elman 17-5r-4
  s.head = Head::Supervisor;
  s.behaviors.push_back({"classical", FixedController{classical, genome_for(*classical)}});
  s.behaviors.push_back({"symbolic", FixedController{symbolic, genome_for(*symbolic)}});
  s.behaviors.push_back({"spin", BehaviorCall{spin(), {0.4, 0.6}}});
  s.behaviors.push_back({"stop", BehaviorCall{stop(), {}}});
  const std::vector<double> g = genome_for(s);
  const std::vector<double> g2(g.rbegin(), g.rend());
  Controller c(s, g);
  int behaviors_used = 0;
  expect_no_allocation(
      c, 2000,
      [&](int t, expr::Frame& f) {
        f[0] = std::sin(0.11 * t);  // slots 0..4 feed the supervisor too: vary the choice
        f[1] = std::cos(0.07 * t);
        if (t % 250 == 0) c.reset();
        if (t == 1000) c.rebind(g2);
      },
      [&] {
        for (const std::int64_t u : c.usage()) behaviors_used += u > 0 ? 1 : 0;
        c.clear_usage();
      });
  EXPECT_GE(behaviors_used, 2);
}

}  // namespace
}  // namespace esc::control
