// Supervisors: a network whose outputs choose, by argmax, which behavior acts this step.
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "runtime/control/controller.hpp"
#include "tests/control/behaviors.hpp"

namespace esc::control {
namespace {

using namespace testing;  // NOLINT

// A classical Elman sub-controller: ir[0], ir[1] -> 2r -> 2 (16 weights).
std::shared_ptr<const ControllerSpec> elman_classical() {
  auto s = std::make_shared<ControllerSpec>();
  s->name = "avoid";
  s->mlp.inputs = {expr::slot::ir, expr::slot::ir + 1};
  s->mlp.hidden = {2};
  s->mlp.kind = NetworkKind::Elman;
  return s;
}
const std::vector<double> kElmanGenome = {0.1,  0.5, -0.3, 0.9, -0.6, -0.2, 0.4, 0.8,
                                          0.3,  0.7, 0.05, 1.0, -0.5, -0.1, 0.3, 0.7};

// A symbolic MLP sub-controller: ir[0..1] -> 3 -> [forward, left, right] (3*3 + 6*4 = 33).
std::shared_ptr<const ControllerSpec> mlp_symbolic() {
  auto s = std::make_shared<ControllerSpec>();
  s->name = "sweep";
  s->mlp.inputs = {expr::slot::ir, expr::slot::ir + 1};
  s->mlp.hidden = {3};
  s->head = Head::Symbolic;
  s->actions = {forward(), left(), right()};
  return s;
}
std::vector<double> wavy(std::size_t n, double k) {
  std::vector<double> g(n);
  for (std::size_t i = 0; i < n; ++i) g[i] = std::sin(k * static_cast<double>(i) + 0.3);
  return g;
}

// Supervisor reading ir[2] with no hidden layer: output j = logistic(bias_j + w_j ir[2]),
// genome [bias_0, w_0, bias_1, w_1, ...]. Behaviors:
//   0: forward(0.3)   1: spin(0.2, 0.7)   2: Elman classical   3: MLP symbolic
ControllerSpec supervisor() {
  ControllerSpec s;
  s.name = "cs";
  s.mlp.inputs = {expr::slot::ir + 2};
  s.head = Head::Supervisor;
  s.behaviors.push_back({"fwd", BehaviorCall{forward(), {0.3}}});
  s.behaviors.push_back({"spin", BehaviorCall{spin(), {0.2, 0.7}}});
  s.behaviors.push_back({"avoid", FixedController{elman_classical(), kElmanGenome}});
  s.behaviors.push_back({"sweep", FixedController{mlp_symbolic(), wavy(33, 0.9)}});
  return s;
}

// Weights making output k the largest whatever the input.
std::vector<double> forcing(std::size_t behaviors, std::size_t k) {
  std::vector<double> g(2 * behaviors, 0.0);
  g[2 * k] = 5.0;
  return g;
}

void fill(expr::Frame& f, int t) {
  for (expr::Slot i = 0; i < expr::kIrCount; ++i)
    f[expr::slot::ir + i] = 0.5 + 0.5 * std::sin(0.37 * t + 1.3 * i);
}

TEST(Supervisor, SpecCountsOneOutputPerBehavior) {
  const ControllerSpec s = supervisor();
  EXPECT_EQ(s.output_count(), 4);
  EXPECT_EQ(s.genome_size(), 8u);  // its own network only
  EXPECT_EQ(s.architecture(), "1-4");
  EXPECT_EQ(s.choice_names(), (std::vector<std::string>{"fwd", "spin", "avoid", "sweep"}));
}

TEST(Supervisor, BehaviorCallRunsWithItsArguments) {
  const ControllerSpec s = supervisor();
  for (std::size_t k : {0u, 1u}) {
    const std::vector<double> g = forcing(4, k);
    Controller c(s, g);
    expr::Frame f{};
    fill(f, 3);
    const WheelCommand w = c.step(f);

    const auto& call = std::get<BehaviorCall>(s.behaviors[k].what);
    expr::Frame alone{};
    fill(alone, 3);
    for (std::size_t i = 0; i < call.args.size(); ++i) alone[expr::slot::param + i] = call.args[i];
    const WheelCommand r = run_behavior(call.behavior, alone);
    EXPECT_EQ(w.left, r.left);
    EXPECT_EQ(w.right, r.right);
    EXPECT_EQ(c.last_action(), static_cast<int>(k));
    EXPECT_EQ(c.usage()[k], 1);
  }
  // spin(0.2, 0.7) is wheels(a, -b).
  const std::vector<double> g = forcing(4, 1);
  Controller c(s, g);
  expr::Frame f{};
  const WheelCommand w = c.step(f);
  EXPECT_EQ(w.left, 0.2);
  EXPECT_EQ(w.right, -0.7);
}

TEST(Supervisor, FixedSubControllersRunExactlyAsAlone) {
  const ControllerSpec s = supervisor();
  for (std::size_t k : {2u, 3u}) {
    const std::vector<double> g = forcing(4, k);
    Controller c(s, g);
    const auto& fixed = std::get<FixedController>(s.behaviors[k].what);
    Controller alone(*fixed.spec, fixed.genome);
    expr::Frame f{};
    expr::Frame fa{};
    for (int t = 0; t < 20; ++t) {
      fill(f, t);
      fill(fa, t);
      const WheelCommand w = c.step(f);
      const WheelCommand r = alone.step(fa);
      EXPECT_EQ(w.left, r.left) << "behavior " << k << " step " << t;
      EXPECT_EQ(w.right, r.right) << "behavior " << k << " step " << t;
      EXPECT_EQ(c.last_action(), static_cast<int>(k));
      ASSERT_NE(c.sub_controller(k), nullptr);
      EXPECT_EQ(c.sub_controller(k)->last_action(), alone.last_action());
    }
    for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(c.usage()[i], i == k ? 20 : 0);
    if (k == 3) {  // the symbolic sub-controller counts its own actions
      const auto sub = c.sub_controller(k)->usage();
      const auto ref = alone.usage();
      ASSERT_EQ(sub.size(), 3u);
      for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(sub[i], ref[i]);
    }
  }
  const std::vector<double> g0 = forcing(4, 0);
  Controller c(s, g0);
  EXPECT_EQ(c.sub_controller(0), nullptr);
  EXPECT_EQ(c.sub_controller(1), nullptr);
  EXPECT_NE(c.sub_controller(2), nullptr);
  EXPECT_EQ(c.sub_controller(4), nullptr);
}

TEST(Supervisor, TieGoesToTheFirstBehavior) {
  const ControllerSpec s = supervisor();
  const std::vector<double> g(8, 0.0);  // all outputs 0.5
  Controller c(s, g);
  expr::Frame f{};
  const WheelCommand w = c.step(f);
  EXPECT_EQ(c.last_action(), 0);
  EXPECT_EQ(w.left, 0.3);
}

// Two sub-controllers with the same Elman spec and genome; the supervisor picks the first
// when ir[2] > 0.5, else the second.
ControllerSpec twin_supervisor() {
  ControllerSpec s;
  s.name = "twins";
  s.mlp.inputs = {expr::slot::ir + 2};
  s.head = Head::Supervisor;
  const auto sub = elman_classical();
  s.behaviors.push_back({"a", FixedController{sub, kElmanGenome}});
  s.behaviors.push_back({"b", FixedController{sub, kElmanGenome}});
  return s;
}
const std::vector<double> kTwinGenome = {-5.0, 10.0, 5.0, -10.0};

struct TwinStep {
  double choose;  // ir[2]
  double x0, x1;  // ir[0], ir[1]: the sub-controllers' inputs
};
const TwinStep kTwinSteps[] = {
    {0.9, 0.6, 0.2}, {0.8, -0.4, 0.9}, {0.1, 0.1, -0.7}, {0.7, 0.3, 0.3}, {0.2, 0.5, 0.5}};

expr::Frame twin_frame(const TwinStep& s) {
  expr::Frame f{};
  f[expr::slot::ir] = s.x0;
  f[expr::slot::ir + 1] = s.x1;
  f[expr::slot::ir + 2] = s.choose;
  return f;
}

TEST(Supervisor, EachSubControllerKeepsItsOwnState) {
  const ControllerSpec s = twin_supervisor();
  Controller c(s, kTwinGenome);
  // References: one standalone controller per behavior, stepped only when it is chosen.
  const auto sub = elman_classical();
  Controller ref_a(*sub, kElmanGenome);
  Controller ref_b(*sub, kElmanGenome);
  for (const TwinStep& t : kTwinSteps) {
    expr::Frame f = twin_frame(t);
    expr::Frame fr = twin_frame(t);
    const WheelCommand w = c.step(f);
    const bool a = t.choose > 0.5;
    const WheelCommand r = (a ? ref_a : ref_b).step(fr);
    EXPECT_EQ(c.last_action(), a ? 0 : 1);
    EXPECT_EQ(w.left, r.left);
    EXPECT_EQ(w.right, r.right);
  }
  EXPECT_EQ(c.usage()[0], 3);
  EXPECT_EQ(c.usage()[1], 2);

  // Had the twins shared their state (or had both stepped every time), step 2 (the first
  // of b) would not equal a fresh network's first step.
  Controller fresh(*sub, kElmanGenome);
  Controller c2(s, kTwinGenome);
  for (int i = 0; i < 2; ++i) {
    expr::Frame f = twin_frame(kTwinSteps[i]);
    (void)c2.step(f);
  }
  expr::Frame f = twin_frame(kTwinSteps[2]);
  expr::Frame fr = twin_frame(kTwinSteps[2]);
  const WheelCommand w = c2.step(f);
  const WheelCommand r = fresh.step(fr);
  EXPECT_EQ(w.left, r.left);
  EXPECT_EQ(w.right, r.right);
}

TEST(Supervisor, ResetResetsSubControllersButKeepsUsage) {
  const ControllerSpec s = twin_supervisor();
  Controller used(s, kTwinGenome);
  for (const TwinStep& t : kTwinSteps) {
    expr::Frame f = twin_frame(t);
    (void)used.step(f);
  }
  used.reset();
  EXPECT_EQ(used.last_action(), -1);
  Controller fresh(s, kTwinGenome);
  for (const TwinStep& t : kTwinSteps) {
    expr::Frame f = twin_frame(t);
    expr::Frame g = twin_frame(t);
    const WheelCommand a = used.step(f);
    const WheelCommand b = fresh.step(g);
    EXPECT_EQ(a.left, b.left);
    EXPECT_EQ(a.right, b.right);
  }
  EXPECT_EQ(used.usage()[0], 6);  // counted over both epochs
  EXPECT_EQ(used.usage()[1], 4);
  used.clear_usage();
  EXPECT_EQ(used.usage()[0], 0);
  EXPECT_EQ(used.usage()[1], 0);
}

TEST(Supervisor, RebindClearsUsageIncludingSubControllers) {
  ControllerSpec s = supervisor();
  const std::vector<double> g3 = forcing(4, 3);
  Controller c(s, g3);
  expr::Frame f{};
  fill(f, 1);
  (void)c.step(f);
  ASSERT_EQ(c.usage()[3], 1);
  const std::vector<double> g = forcing(4, 0);
  c.rebind(g);
  for (std::int64_t u : c.usage()) EXPECT_EQ(u, 0);
  for (std::int64_t u : c.sub_controller(3)->usage()) EXPECT_EQ(u, 0);
  (void)c.step(f);
  EXPECT_EQ(c.last_action(), 0);
}

TEST(Supervisor, ElmanSupervisorRuns) {
  ControllerSpec s = supervisor();
  s.mlp.inputs = seventeen_inputs();
  s.mlp.hidden = {5};
  s.mlp.kind = NetworkKind::Elman;
  ASSERT_EQ(s.genome_size(), 139u);
  const std::vector<double> g = wavy(139, 2.3);
  Controller c(s, g);
  expr::Frame f{};
  for (int t = 0; t < 100; ++t) {
    fill(f, t);
    const WheelCommand w = c.step(f);
    EXPECT_GE(c.last_action(), 0);
    EXPECT_LT(c.last_action(), 4);
    EXPECT_GE(w.left, -1.0);
    EXPECT_LE(w.left, 1.0);
  }
  std::int64_t total = 0;
  for (std::int64_t u : c.usage()) total += u;
  EXPECT_EQ(total, 100);
}

TEST(Supervisor, NestedSupervisorRunsTheInnerChoice) {
  auto inner = std::make_shared<ControllerSpec>(supervisor());
  ControllerSpec outer;
  outer.name = "outer";
  outer.mlp.inputs = {expr::slot::ir};
  outer.head = Head::Supervisor;
  outer.behaviors.push_back({"stop", BehaviorCall{stop(), {}}});
  outer.behaviors.push_back({"inner", FixedController{inner, forcing(4, 1)}});
  const std::vector<double> g = forcing(2, 1);
  Controller c(outer, g);
  expr::Frame f{};
  const WheelCommand w = c.step(f);
  EXPECT_EQ(c.last_action(), 1);
  EXPECT_EQ(c.sub_controller(1)->last_action(), 1);
  EXPECT_EQ(w.left, 0.2);
  EXPECT_EQ(w.right, -0.7);
}

TEST(Supervisor, RejectsSpecsItCannotRun) {
  ControllerSpec none = supervisor();
  none.behaviors.clear();
  EXPECT_THROW(Controller(none, std::vector<double>(none.genome_size())), std::invalid_argument);

  ControllerSpec bad_genome = supervisor();
  std::get<FixedController>(bad_genome.behaviors[2].what).genome.pop_back();
  try {
    Controller c(bad_genome, std::vector<double>(8));
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("'avoid'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("16"), std::string::npos) << msg;
    EXPECT_NE(msg.find("15"), std::string::npos) << msg;
  }

  ControllerSpec no_spec = supervisor();
  std::get<FixedController>(no_spec.behaviors[3].what).spec = nullptr;
  EXPECT_THROW(Controller(no_spec, std::vector<double>(8)), std::invalid_argument);

  ControllerSpec bad_args = supervisor();
  std::get<BehaviorCall>(bad_args.behaviors[1].what).args = {0.5};
  EXPECT_THROW(Controller(bad_args, std::vector<double>(8)), std::invalid_argument);

  ControllerSpec bad_sub = supervisor();
  auto broken = std::make_shared<ControllerSpec>(*elman_classical());
  broken->mlp.hidden = {2, 2};
  bad_sub.behaviors[2].what = FixedController{broken, std::vector<double>(broken->genome_size())};
  EXPECT_THROW(Controller(bad_sub, std::vector<double>(8)), std::invalid_argument);

  ControllerSpec mixed = supervisor();
  mixed.actions = {forward()};
  EXPECT_THROW(Controller(mixed, std::vector<double>(8)), std::invalid_argument);

  ControllerSpec classical_with_behaviors;
  classical_with_behaviors.mlp.inputs = {expr::slot::ir};
  classical_with_behaviors.behaviors = supervisor().behaviors;
  EXPECT_THROW(Controller(classical_with_behaviors, std::vector<double>(4)),
               std::invalid_argument);
}

TEST(Supervisor, RejectsASupervisorThatContainsItself) {
  auto self = std::make_shared<ControllerSpec>();
  self->name = "loop";
  self->mlp.inputs = {expr::slot::ir};
  self->head = Head::Supervisor;
  self->behaviors.push_back({"again", FixedController{self, std::vector<double>(2)}});
  EXPECT_THROW(Controller(*self, std::vector<double>(2)), std::invalid_argument);
  self->behaviors.clear();  // break the ownership cycle
}

}  // namespace
}  // namespace esc::control
