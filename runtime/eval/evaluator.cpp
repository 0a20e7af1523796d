#include "runtime/eval/evaluator.hpp"

#include <array>

#include "runtime/control/controller.hpp"
#include "runtime/core/rng.hpp"
#include "runtime/eval/observe.hpp"

namespace esc::eval {

namespace {

bool any_stop(const FitnessSpec& f, const expr::Frame& frame) noexcept {
  for (const expr::Program& p : f.stop_when)
    if (p.eval(frame) != 0.0) return true;
  return false;
}

}  // namespace

Evaluator::Evaluator(const ExperimentSpec& spec) : spec_(&spec), world_(spec.arena, spec.robot) {}

Evaluation Evaluator::evaluate(const control::ControllerSpec& controller,
                               std::span<const double> genome, std::uint64_t seed) {
  const ExperimentSpec& s = *spec_;
  control::Controller ctl(controller, genome);
  std::array<double, sim::kIrSensors> ir{};
  expr::Frame frame{};
  Evaluation result;
  for (int epoch = 0; epoch < s.epochs; ++epoch) {
    Rng rng(seed, {static_cast<std::uint64_t>(epoch)});
    world_.reset(s.arena.fixed_start ? *s.arena.fixed_start : world_.random_free_pose(rng));
    ctl.reset();
    frame.fill(0.0);
    // The reading taken after each physics step serves both that step's fitness term and
    // the next step's control input: the robot has not moved in between.
    world_.read_ir(ir, rng);
    observe_robot(world_, ir, frame);
    for (int step = 0; step < s.steps; ++step) {
      observe_clock(epoch, step, s.robot.control_step_s, frame);
      const control::WheelCommand cmd = ctl.step(frame);
      world_.step(cmd.left, cmd.right);
      world_.read_ir(ir, rng);
      observe_robot(world_, ir, frame);
      ++result.steps;
      result.fitness += s.fitness.step.eval(frame);
      if (any_stop(s.fitness, frame)) break;
    }
  }
  return result;
}

}  // namespace esc::eval
