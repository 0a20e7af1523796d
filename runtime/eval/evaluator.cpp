#include "runtime/eval/evaluator.hpp"

#include <algorithm>
#include <array>

#include "runtime/control/controller.hpp"
#include "runtime/core/rng.hpp"
#include "runtime/eval/observe.hpp"
#include "runtime/evo/gp/codec.hpp"
#include "runtime/tree_control/tree_driver.hpp"

namespace esc::eval {

namespace {

bool any_stop(const FitnessSpec& f, const expr::Frame& frame) noexcept {
  for (const expr::Program& p : f.stop_when)
    if (p.eval(frame) != 0.0) return true;
  return false;
}

void report_step(TraceSink& trace, int epoch, int step, const sim::World& world,
                 const std::array<double, sim::kIrSensors>& ir, const std::array<double, sim::kLightSensors>& light,
                 const control::WheelCommand& cmd, int action, double fitness) {
  const sim::RobotState& state = world.state();
  TraceStep t;
  t.energy = state.floor.energy;
  const auto zones = world.zone_centers();
  t.zone_count = std::min(zones.size(), t.zones.size());
  std::copy_n(zones.begin(), t.zone_count, t.zones.begin());
  t.epoch = epoch;
  t.step = step;
  t.pose = state.pose;
  t.ir = ir;
  t.light = light;
  t.left_command = cmd.left;
  t.right_command = cmd.right;
  t.left_speed_mps = state.wheel_speed_mps[0];
  t.right_speed_mps = state.wheel_speed_mps[1];
  t.action = action;
  t.fitness = fitness;
  t.collided = state.collided;
  trace.on_step(t);
}

}  // namespace

Evaluator::Evaluator(const ExperimentSpec& spec) : spec_(&spec), world_(spec.arena, spec.robot) {}

Evaluation Evaluator::evaluate(const control::ControllerSpec& controller,
                               std::span<const double> genome, std::uint64_t seed,
                               TraceSink* trace) {
  if (controller.is_tree()) return evaluate(controller, evo::gp::decode(genome, *controller.primitives), seed, trace);
  control::Controller ctl(controller, genome);
  return run(ctl, reads_slot(spec_->fitness, controller, expr::slot::noise), seed, trace);
}

Evaluation Evaluator::evaluate(const control::ControllerSpec& controller, const evo::gp::Tree& tree,
                               std::uint64_t seed, TraceSink* trace) {
  tree_control::TreeDriver ctl(controller, tree);
  return run(ctl, reads_slot(spec_->fitness, controller, expr::slot::noise), seed, trace);
}

template <class Driver>
Evaluation Evaluator::run(Driver& ctl, bool noise, std::uint64_t seed, TraceSink* trace) {
  const ExperimentSpec& s = *spec_;
  std::array<double, sim::kIrSensors> ir{};
  std::array<double, sim::kLightSensors> light{};
  expr::Frame frame{};
  // The reading taken after each physics step serves both that step's fitness term and
  // the next step's control input: the robot has not moved in between.
  const auto sense = [&](Rng& rng) {
    world_.read_ir(ir, rng);
    world_.read_light(light, rng);
    observe_light(light, frame);
    observe_robot(world_, ir, frame);
  };
  Evaluation result;
  for (int epoch = 0; epoch < s.epochs; ++epoch) {
    Rng rng(seed, {static_cast<std::uint64_t>(epoch)});
    world_.begin_epoch(rng);   // random zones, then the start pose, then reset
    ctl.reset();
    frame.fill(0.0);
    sense(rng);
    for (int step = 0; step < s.steps; ++step) {
      observe_clock(epoch, step, s.robot.control_step_s, frame);
      if (noise) observe_noise(seed, epoch, step, frame);
      const control::WheelCommand cmd = ctl.step(frame);
      world_.step(cmd.left, cmd.right);
      sense(rng);
      ++result.steps;
      result.fitness += s.fitness.step.eval(frame);
      if (trace != nullptr) [[unlikely]]
        report_step(*trace, epoch, step, world_, ir, light, cmd, ctl.last_action(), result.fitness);
      if (any_stop(s.fitness, frame) || world_.state().floor.energy_empty) break;
    }
  }
  return result;
}

}  // namespace esc::eval
