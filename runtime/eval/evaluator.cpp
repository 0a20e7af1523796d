#include "runtime/eval/evaluator.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

#include "runtime/control/controller.hpp"
#include "runtime/core/rng.hpp"
#include "runtime/eval/observe.hpp"
#include "runtime/evo/gp/codec.hpp"
#include "runtime/tree_control/tree_driver.hpp"

namespace esc::eval {

namespace {

// The fitness sum saturates at +-kSaturation like the VM's operators (one constant term of
// 1e308 over two steps would otherwise reach infinity), and a NaN, which no operator makes
// (only a broken observable could), is the lowest fitness. Identical to a plain sum within
// the limits. The generation's statistics count evaluations at the limit (`saturated`).
double add_term(double sum, double term) noexcept {
  const double s = sum + term;
  if (std::isnan(s)) return -expr::kSaturation;
  return std::clamp(s, -expr::kSaturation, expr::kSaturation);
}


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

Evaluator::Evaluator(const ExperimentSpec& spec)
    : spec_(&spec), world_(spec.arena, spec.robot), end_frame_(expr::aggregate::count + spec.choice_ids, 0.0) {
  for (const auto* term : {&spec.fitness.epoch_end, &spec.fitness.evaluation_end}) {
    if (!*term) continue;
    if (!(*term)->complete()) throw std::invalid_argument("fitness '" + spec.fitness.name + "': an end term is incomplete");
    for (const expr::Instr& in : (*term)->code())
      if (in.op == expr::Op::Load && in.slot >= end_frame_.size())
        throw std::invalid_argument("fitness '" + spec.fitness.name + "': an end term reads slot " +
                                    std::to_string(in.slot) + ", beyond the frame and the experiment's " +
                                    std::to_string(spec.choice_ids) + " choice counts");
  }
}

Evaluation Evaluator::evaluate(const control::ControllerSpec& controller,
                               std::span<const double> genome, std::uint64_t seed,
                               TraceSink* trace) {
  if (controller.is_tree()) return evaluate(controller, evo::gp::decode(genome, *controller.primitives), seed, trace);
  control::Controller ctl(controller, genome, &tree_control::make_actor);
  return run(controller, ctl, reads_slot(spec_->fitness, controller, expr::slot::noise), seed, trace);
}

Evaluation Evaluator::evaluate(const control::ControllerSpec& controller, const evo::gp::Tree& tree,
                               std::uint64_t seed, TraceSink* trace) {
  tree_control::TreeDriver ctl(controller, tree);
  return run(controller, ctl, reads_slot(spec_->fitness, controller, expr::slot::noise), seed, trace);
}

double Evaluator::end_term(const expr::Program& term, const control::ControllerSpec& controller,
                           const expr::Frame& frame, std::int64_t steps, std::span<const std::int64_t> usage,
                           std::span<const std::int64_t> before) {
  std::copy(frame.begin(), frame.end(), end_frame_.begin());
  std::fill(end_frame_.begin() + expr::aggregate::steps, end_frame_.end(), 0.0);
  end_frame_[expr::aggregate::steps] = static_cast<double>(steps);
  for (std::size_t i = 0; i < usage.size(); ++i) {
    const int id = controller.choice_id(static_cast<int>(i));
    if (id < 0 || expr::aggregate::count + static_cast<std::size_t>(id) >= end_frame_.size()) continue;
    end_frame_[expr::aggregate::count + static_cast<std::size_t>(id)] +=
        static_cast<double>(usage[i] - (i < before.size() ? before[i] : 0));
  }
  return term.eval(end_frame_);
}

template <class Driver>
Evaluation Evaluator::run(const control::ControllerSpec& controller, Driver& ctl, bool noise, std::uint64_t seed,
                          TraceSink* trace) {
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
    epoch_start_.assign(ctl.usage().begin(), ctl.usage().end());   // no allocation once it has grown
    const std::int64_t steps_before = result.steps;
    for (int step = 0; step < s.steps; ++step) {
      observe_clock(epoch, step, s.robot.control_step_s, frame);
      if (noise) observe_noise(seed, epoch, step, frame);
      const control::WheelCommand cmd = ctl.step(frame);
      frame[expr::slot::acting] = controller.choice_id(ctl.last_action());
      world_.step(cmd.left, cmd.right, rng);
      sense(rng);
      ++result.steps;
      result.fitness = add_term(result.fitness, s.fitness.step.eval(frame));
      if (trace != nullptr) [[unlikely]]
        report_step(*trace, epoch, step, world_, ir, light, cmd, ctl.last_action(), result.fitness);
      if (any_stop(s.fitness, frame) || world_.state().floor.energy_empty) break;
    }
    if (s.fitness.epoch_end)
      result.fitness += end_term(*s.fitness.epoch_end, controller, frame, result.steps - steps_before, ctl.usage(),
                                 epoch_start_);
  }
  if (s.fitness.evaluation_end)
    result.fitness += end_term(*s.fitness.evaluation_end, controller, frame, result.steps, ctl.usage(), {});
  result.usage.assign(ctl.usage().begin(), ctl.usage().end());
  return result;
}

}  // namespace esc::eval
