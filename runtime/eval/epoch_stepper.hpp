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
// A group (ExperimentSpec::robots > 1) has a frame per robot: every robot's controller decides
// on its own frame, then act() steps the group once and each frame observes its robot; the
// step term is the robots' terms reduced as the fitness says (their mean unless `over robots`
// says otherwise), and a stop condition of any robot ends the epoch
// (docs/groups.md). Frame 0 is a robot alone's.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "runtime/control/behavior.hpp"
#include "runtime/core/rng.hpp"
#include "runtime/eval/evaluator.hpp"
#include "runtime/eval/experiment.hpp"
#include "runtime/eval/observe.hpp"
#include "runtime/expr/observables.hpp"
#include "runtime/expr/program.hpp"
#include "runtime/sim/world.hpp"

namespace esc::eval {

// The world an evaluation of `spec` steps: its arena, its robots, where they start.
[[nodiscard]] sim::World world_of(const ExperimentSpec& spec);

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
  // `spec` and `world` (built for spec's arena and robots) must outlive the stepper.
  // `reads`: what anything reads of the observables written only then (stepper_reads); a
  // group's own observables are always written for a group.
  EpochStepper(const ExperimentSpec& spec, sim::World& world, const StepperReads& reads)
      : spec_(&spec), world_(&world), noise_(reads.noise), group_(reads.group || world.robots() > 1), pairs_(reads.pairs),
        frames_(world.robots()), ir_(world.robots()), light_(world.robots()), commands_(world.robots()),
        cluster_parent_(world.robots()), cluster_size_(world.robots()), widest_(widest(world)) {}

  // Epoch `epoch` (from 0) of the evaluation with seed `seed`, its stream Rng(seed, {epoch}):
  // zones, start pose and reset drawn from it, the frame zeroed, then the first reading.
  void begin(std::uint64_t seed, int epoch);

  // Writes the clock observables (and `noise`) of the coming step: with the last reading,
  // what the controller decides on.
  void observe() noexcept {
    for (expr::Frame& frame : frames_) {
      observe_clock(epoch_, step_, spec_->robot.control_step_s, frame);
      if (noise_) observe_noise(seed_, epoch_, step_, frame);
    }
  }

  // The frame robot `robot`'s controller reads; a symbolic head writes its action's
  // parameters into it.
  [[nodiscard]] expr::Frame& frame(std::size_t robot = 0) noexcept { return frames_[robot]; }
  [[nodiscard]] const expr::Frame& frame(std::size_t robot = 0) const noexcept { return frames_[robot]; }

  // Robot `robot`'s fitness step term on its frame: the group's step term is their mean.
  [[nodiscard]] double term(std::size_t robot) const noexcept { return spec_->fitness.step.eval(frames_[robot]); }
  [[nodiscard]] std::size_t robots() const noexcept { return frames_.size(); }

  // `program` on every robot's frame, reduced by `over` (Mean, Sum, Min or Max): its value on
  // the one frame of a robot alone.
  [[nodiscard]] double over_robots(const expr::Program& program, Reduction over) const noexcept {
    if (frames_.size() == 1) return program.eval(frames_[0]);
    return reduce_over_robots(frames_.size(), over, [&](std::size_t i) { return program.eval(frames_[i]); });
  }

  // The coming step with command `cmd`, chosen by the experiment-wide choice `acting`
  // (control::Choice::id, -1 for none): physics, the reading after it, the step term and
  // the stop conditions, all on the frame of this step.
  StepOutcome act(const control::WheelCommand& cmd, int acting) {
    frames_[0][expr::slot::acting] = acting;
    world_->step(cmd.left, cmd.right, rng_);
    return after_step();
  }
  // A group's step: robot i's command and choice (-1 for none) are cmds[i] and acting[i].
  StepOutcome act(std::span<const control::WheelCommand> cmds, std::span<const int> acting) {
    if (frames_.size() == 1) return act(cmds[0], acting[0]);
    for (std::size_t i = 0; i < frames_.size(); ++i) {
      frames_[i][expr::slot::acting] = acting[i];
      commands_[i] = {cmds[i].left, cmds[i].right};
    }
    world_->step(commands_, rng_);
    return after_step();
  }

  // The step just taken as a replay records it for robot `robot`: `cmd` and `action` (the
  // controller's choice index, -1 for none) that led to it, `fitness` the evaluation's so far.
  [[nodiscard]] TraceStep traced(const control::WheelCommand& cmd, int action, double fitness,
                                 std::size_t robot = 0) const;

  [[nodiscard]] int epoch() const noexcept { return epoch_; }
  [[nodiscard]] int steps_taken() const noexcept { return step_; }   // in this epoch
  // The last reading (taken after the last step's physics, or at the epoch's start).
  [[nodiscard]] const std::array<double, sim::kIrSensors>& ir() const noexcept { return ir_[0]; }
  [[nodiscard]] const std::array<double, sim::kLightSensors>& light() const noexcept { return light_[0]; }
  [[nodiscard]] const sim::World& world() const noexcept { return *world_; }

 private:
  // The group's widest body's rangefinders, radars, ground sensors and bumpers: the shape of
  // every traced step (the store's), a robot reading 0 from a sensor its body lacks.
  struct SensorCounts {
    std::size_t ranges = 0, radars = 0, grounds = 0, bumpers = 0;
  };
  static SensorCounts widest(const sim::World& world) noexcept;

  // The reading after each physics step serves that step's fitness term and the next step's
  // control input: the robot has not moved in between.
  // A group's robots are read in robot order, each its IR then its light (the noise drawn so).
  void sense() {
    for (std::size_t i = 0; i < frames_.size(); ++i) {
      world_->read_ir(ir_[i], rng_, i);
      world_->read_light(light_[i], rng_, i);
      observe_light(light_[i], frames_[i]);
      observe_robot(*world_, i, ir_[i], frames_[i]);
    }
    if (group_) observe_group(*world_, start_centroid_, pairs_, frames_);
    if (!spec_->cluster_radii.empty())
      observe_clusters(*world_, spec_->cluster_radii, frames_, cluster_parent_, cluster_size_);
  }

  StepOutcome after_step() {
    sense();
    ++step_;
    const double term = over_robots(spec_->fitness.step, spec_->fitness.over_robots);
    return {term, stops()};
  }

  // Whether a stop condition of the fitness fires on a robot's frame, or a robot's
  // accumulator ran empty.
  [[nodiscard]] bool stops() const noexcept {
    for (std::size_t i = 0; i < frames_.size(); ++i) {
      for (const expr::Program& p : spec_->fitness.stop_when)
        if (p.eval(frames_[i]) != 0.0) return true;
      if (world_->state(i).floor.energy_empty) return true;
    }
    return false;
  }

  const ExperimentSpec* spec_;
  sim::World* world_;
  bool noise_;
  bool group_;
  bool pairs_;
  Rng rng_{0};
  std::uint64_t seed_ = 0;
  int epoch_ = 0;
  int step_ = 0;
  sim::Vec2 start_centroid_;
  std::vector<expr::Frame> frames_;
  std::vector<std::array<double, sim::kIrSensors>> ir_;
  std::vector<std::array<double, sim::kLightSensors>> light_;
  std::vector<sim::DriveCommand> commands_;
  std::vector<std::size_t> cluster_parent_, cluster_size_;   // observe_clusters' scratch, a robot each
  SensorCounts widest_;
};

}  // namespace esc::eval
