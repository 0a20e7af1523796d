#include "runtime/expr/program.hpp"

#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "runtime/expr/observables.hpp"

namespace esc::expr {
namespace {

Frame frame_with(Slot s, double v) {
  Frame f{};
  f[s] = v;
  return f;
}

TEST(Program, EvaluatesPostfix) {
  // (forward_speed max 0) * (1 - sqrt(wheel_diff))
  Program p;
  p.push_load(slot::forward_speed);
  p.push_const(0.0);
  p.push_op(Op::Max);
  p.push_const(1.0);
  p.push_load(slot::wheel_diff);
  p.push_op(Op::Sqrt);
  p.push_op(Op::Sub);
  p.push_op(Op::Mul);
  ASSERT_TRUE(p.complete());
  Frame f{};
  f[slot::forward_speed] = 0.8;
  f[slot::wheel_diff] = 0.25;
  EXPECT_DOUBLE_EQ(p.eval(f), 0.8 * 0.5);
  f[slot::forward_speed] = -0.8;
  EXPECT_DOUBLE_EQ(p.eval(f), 0.0);
  EXPECT_EQ(p.disassemble(), "load 1 const 0 max const 1 load 2 sqrt sub mul");
}

TEST(Program, SelectAndClamp) {
  Program p;  // if collision then -1 else clamp(ir[0] * 3, 0, 1)
  p.push_load(slot::collision);
  p.push_const(-1.0);
  p.push_load(slot::ir);
  p.push_const(3.0);
  p.push_op(Op::Mul);
  p.push_const(0.0);
  p.push_const(1.0);
  p.push_op(Op::Clamp);
  p.push_op(Op::Select);
  Frame f = frame_with(slot::ir, 0.2);
  EXPECT_DOUBLE_EQ(p.eval(f), 0.6000000000000001);
  f[slot::ir] = 0.9;
  EXPECT_DOUBLE_EQ(p.eval(f), 1.0);
  f[slot::collision] = 1.0;
  EXPECT_DOUBLE_EQ(p.eval(f), -1.0);
}

TEST(Program, OperatorsAreTotal) {
  const auto binary = [](double a, double b, Op op) {
    Program p;
    p.push_const(a);
    p.push_const(b);
    p.push_op(op);
    return p.eval(Frame{});
  };
  const auto unary = [](double a, Op op) {
    Program p;
    p.push_const(a);
    p.push_op(op);
    return p.eval(Frame{});
  };
  EXPECT_EQ(binary(1.0, 0.0, Op::Div), 0.0);
  EXPECT_EQ(unary(-4.0, Op::Sqrt), 0.0);
  EXPECT_EQ(unary(0.0, Op::Log), 0.0);
  EXPECT_TRUE(std::isfinite(unary(1e6, Op::Exp)));
  EXPECT_TRUE(std::isfinite(binary(1e300, 1e300, Op::Mul)));
  EXPECT_TRUE(std::isfinite(binary(-2.0, 0.5, Op::Pow)));
  EXPECT_EQ(binary(2.0, 10.0, Op::Pow), 1024.0);
  EXPECT_EQ(binary(1.0, 0.0, Op::And), 0.0);
  EXPECT_EQ(binary(1.0, 0.0, Op::Or), 1.0);
  EXPECT_EQ(unary(0.0, Op::Not), 1.0);
}

TEST(Program, BuilderRejectsMissingOperands) {
  Program p;
  p.push_const(1.0);
  EXPECT_THROW(p.push_op(Op::Add), std::logic_error);
  EXPECT_THROW(p.push_op(Op::Const), std::logic_error);
  p.push_const(2.0);
  EXPECT_FALSE([&] { Program q; q.push_const(1); q.push_const(2); return q.complete(); }());
}

TEST(Program, TracksStackDepth) {
  Program p;
  for (int i = 0; i < 10; ++i) p.push_const(i);
  for (int i = 0; i < 9; ++i) p.push_op(Op::Add);
  EXPECT_EQ(p.max_depth(), 10U);
  EXPECT_TRUE(p.complete());
  EXPECT_DOUBLE_EQ(p.eval(Frame{}), 45.0);
}

TEST(Observables, EveryNameResolvesToItsSlots) {
  EXPECT_EQ(find_observable("ir")->first, slot::ir);
  EXPECT_EQ(find_observable("ir")->count, kIrCount);
  EXPECT_TRUE(find_observable("ir")->indexed);
  EXPECT_FALSE(find_observable("speed")->indexed);
  EXPECT_FALSE(find_observable("irr").has_value());
  // None overlaps the behavior parameters, written into the frame while a behavior runs.
  for (const auto& o : kObservables)
    EXPECT_TRUE(o.first + o.count <= slot::param || o.first >= slot::param + kMaxParams) << o.name;
  EXPECT_EQ(find_observable("x")->first, slot::x);
  EXPECT_EQ(find_observable("goal_distance")->first, slot::goal_distance);
  EXPECT_EQ(find_observable("range")->count, kRangeCount);
  EXPECT_TRUE(find_observable("radar")->indexed);
  EXPECT_EQ(find_observable("radar")->first + kRadarCount, find_observable("ground_sensor")->first);
  EXPECT_EQ(find_observable("ground_sensor")->first + kGroundSensorCount, find_observable("bumper")->first);
  EXPECT_EQ(find_observable("bumper")->first + kBumperCount, find_observable("robots")->first);
  EXPECT_EQ(find_observable("spread")->first + 1, find_parametrised("clusters")->first);
  EXPECT_EQ(find_parametrised("cluster_size")->first + kMaxClusterRadii, kFrameSize);
}

}  // namespace
}  // namespace esc::expr
