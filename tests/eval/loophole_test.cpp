// The paper's loophole (section 3.2): without inertia, alternating FORWARD and BACKWARD at
// full speed scores the maximum of the original fitness V (1 - sqrt(dV)) while going
// nowhere. Observables read the physical body, so with motor inertia the same commands
// cover almost no distance per step and score next to nothing.
#include <array>

#include <gtest/gtest.h>

#include "runtime/eval/observe.hpp"
#include "tests/eval/test_experiment.hpp"

namespace esc::eval {
namespace {

double score(bool inertia, bool alternate, int steps) {
  sim::ArenaSpec arena;
  arena.width_m = 1.0;
  arena.height_m = 1.0;
  arena.fixed_start = sim::Pose{0.5, 0.5, 0.0};
  sim::RobotParams robot;
  robot.motor.inertia = inertia;
  sim::World world(arena, robot);
  world.reset(*arena.fixed_start);
  Rng rng(1);
  std::array<double, sim::kIrSensors> ir{};
  expr::Frame frame{};
  expr::Program original;   // speed * (1 - sqrt(wheel_diff))
  original.push_load(expr::slot::speed);
  original.push_const(1.0);
  original.push_load(expr::slot::wheel_diff);
  original.push_op(expr::Op::Sqrt);
  original.push_op(expr::Op::Sub);
  original.push_op(expr::Op::Mul);
  double fitness = 0.0;
  for (int s = 0; s < steps; ++s) {
    const double command = (alternate && s % 2 == 1) ? -1.0 : 1.0;
    world.step(command, command);
    world.read_ir(ir, rng);
    observe_robot(world, 0, ir, frame);
    fitness += original.eval(frame);
  }
  return fitness;
}

TEST(Loophole, ForwardBackwardScoresTheMaximumOnlyWithoutInertia) {
  constexpr int kSteps = 150;
  // Driving straight from the centre of the 1 m arena: 50 steps cover 0.4 m, no wall.
  EXPECT_NEAR(score(false, true, kSteps), kSteps, 1e-6);
  const double straight = score(true, false, 50) / 50.0;
  const double alternating = score(true, true, kSteps) / kSteps;
  EXPECT_GT(straight, 0.9);
  EXPECT_LT(alternating, straight / 3.0);
}

}  // namespace
}  // namespace esc::eval
