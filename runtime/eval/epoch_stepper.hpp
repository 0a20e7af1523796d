#pragma once
// One epoch of an evaluation, one control step at a time:
//   begin:    the epoch's own random stream, random zones, the start pose, a zeroed frame
//             holding the first reading;
//   each step: observe() the clock (and noise) -> the controller reads frame() and decides
//             -> act(): the command and the physics, the next reading, the fitness's step
//             term and stop conditions.
// The evaluator runs every epoch through it, and the Python module's Env (python/src/env.cpp)
// drives the same calls from outside, one step per call: one step loop, so an Env fed the
// actions a genome's network takes computes the doubles an evaluation of that genome does.
// The per-step calls are inline: the evaluator's loop compiles as one function, as before.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "runtime/control/behavior.hpp"
#include "runtime/core/rng.hpp"
#include "runtime/eval/evaluator.hpp"
#include "runtime/eval/experiment.hpp"
#include "runtime/eval/observe.hpp"
#include "runtime/expr/observables.hpp"
#include "runtime/expr/program.hpp"
#include "runtime/sim/world.hpp"

namespace esc::eval {

// What one control step adds to the evaluation.
struct StepOutcome {
  double term = 0.0;   // the fitness's step term, evaluated after the step's physics
  bool stop = false;   // a stop condition fired or the accumulator ran empty: the epoch ends here
};

// The evaluation's fitness after adding a step's term (expr::saturating_add). The
// generation's statistics count evaluations at the limit (`saturated`).
[[nodiscard]] inline double add_fitness(double sum, double term) noexcept { return expr::saturating_add(sum, term); }

class EpochStepper {
 public:
  // `spec` and `world` (built for spec's arena and robot) must outlive the stepper. `noise`:
  // whether anything reads the `noise` observable (reads_slot), which is written only then.
  EpochStepper(const ExperimentSpec& spec, sim::World& world, bool noise) noexcept
      : spec_(&spec), world_(&world), noise_(noise) {}

  // Epoch `epoch` (from 0) of the evaluation with seed `seed`, its stream Rng(seed, {epoch}):
  // zones, start pose and reset drawn from it, the frame zeroed, then the first reading.
  void begin(std::uint64_t seed, int epoch);

  // Writes the clock observables (and `noise`) of the coming step: with the last reading,
  // what the controller decides on.
  void observe() noexcept {
    observe_clock(epoch_, step_, spec_->robot.control_step_s, frame_);
    if (noise_) observe_noise(seed_, epoch_, step_, frame_);
  }

  // The frame the controller reads; a symbolic head writes its action's parameters into it.
  [[nodiscard]] expr::Frame& frame() noexcept { return frame_; }
  [[nodiscard]] const expr::Frame& frame() const noexcept { return frame_; }

  // The coming step with command `cmd`, chosen by the experiment-wide choice `acting`
  // (control::Choice::id, -1 for none): physics, the reading after it, the step term and
  // the stop conditions, all on the frame of this step.
  StepOutcome act(const control::WheelCommand& cmd, int acting) {
    frame_[expr::slot::acting] = acting;
    world_->step(cmd.left, cmd.right, rng_);
    sense();
    ++step_;
    const double term = spec_->fitness.step.eval(frame_);
    return {term, stops() || world_->state().floor.energy_empty};
  }

  // The step just taken as a replay records it: `cmd` and `action` (the controller's choice
  // index, -1 for none) that led to it, `fitness` the evaluation's so far.
  [[nodiscard]] TraceStep traced(const control::WheelCommand& cmd, int action, double fitness) const;

  [[nodiscard]] int epoch() const noexcept { return epoch_; }
  [[nodiscard]] int steps_taken() const noexcept { return step_; }   // in this epoch
  // The last reading (taken after the last step's physics, or at the epoch's start).
  [[nodiscard]] const std::array<double, sim::kIrSensors>& ir() const noexcept { return ir_; }
  [[nodiscard]] const std::array<double, sim::kLightSensors>& light() const noexcept { return light_; }
  [[nodiscard]] const sim::World& world() const noexcept { return *world_; }

 private:
  // The reading after each physics step serves that step's fitness term and the next step's
  // control input: the robot has not moved in between.
  void sense() {
    world_->read_ir(ir_, rng_);
    world_->read_light(light_, rng_);
    observe_light(light_, frame_);
    observe_robot(*world_, ir_, frame_);
  }

  // Whether a stop condition of the fitness fires on the frame.
  [[nodiscard]] bool stops() const noexcept {
    for (const expr::Program& p : spec_->fitness.stop_when)
      if (p.eval(frame_) != 0.0) return true;
    return false;
  }

  const ExperimentSpec* spec_;
  sim::World* world_;
  bool noise_;
  Rng rng_{0};
  std::uint64_t seed_ = 0;
  int epoch_ = 0;
  int step_ = 0;
  std::array<double, sim::kIrSensors> ir_{};
  std::array<double, sim::kLightSensors> light_{};
  expr::Frame frame_{};
};

}  // namespace esc::eval
