#pragma once
// An experiment's epochs stepped from Python, Gymnasium's way: reset() starts an episode, one
// epoch; step(action) is one control step of it (eval::EpochStepper, the evaluator's own step
// code). Episode k after reset(seed=S) is epoch k of the evaluation with seed S: the same
// start pose, noise and `epoch` observable as that epoch of esc's evaluation.
//
// A group's experiment (docs/groups.md) is stepped with every robot's action at once
// (reset_group, step_group: PettingZoo's parallel API, esc.ParallelEnv); reset and step drive
// a robot alone.
//
// Without a controller, the action is the two wheel commands in [-1, 1] and the observation
// the robot's senses: ir[0..7], light[0..7], energy. With a network controller, the
// observation is its network's inputs and the action its network's activated outputs, which
// the controller's head turns into wheel commands as in a run (argmax over actions with their
// parameters, or over supervised behaviors); Policy (policy.hpp) computes them from a genome.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "python/src/compiled_script.hpp"
#include "runtime/control/controller.hpp"
#include "runtime/eval/epoch_stepper.hpp"
#include "runtime/sim/world.hpp"

namespace esc::python {

class Env {
 public:
  // Raises ValueError for an unknown experiment or controller, or a tree controller (it has no
  // network whose outputs an action could be).
  Env(const std::shared_ptr<CompiledScript>& script, const std::string& experiment,
      const std::optional<std::string>& controller, std::uint64_t seed);
  Env(const Env&) = delete;
  Env& operator=(const Env&) = delete;

  using Action = pybind11::array_t<double, pybind11::array::c_style | pybind11::array::forcecast>;

  // The next episode, or epoch 0 of the evaluation with `seed` when one is given:
  // (observation, info). ValueError for a group.
  pybind11::tuple reset(std::optional<std::uint64_t> seed);
  // (observation, reward, terminated, truncated, info). ValueError for a group.
  pybind11::tuple step(const Action& action);
  // A group's: (observations, info), a list of the robots' in robot order.
  pybind11::tuple reset_group(std::optional<std::uint64_t> seed);
  // A group's step with robot i's action actions[i]: (observations, rewards, terminated,
  // truncated, infos), the first two and the last lists in robot order: robot i's reward is
  // its own fitness step term (the group's is their mean), and an episode ends for every robot.
  pybind11::tuple step_group(const std::vector<Action>& actions);
  // Robot `robot` after the last step as a replay records it.
  [[nodiscard]] pybind11::dict state(std::size_t robot = 0) const;
  [[nodiscard]] std::size_t robots() const noexcept { return stepper_.robots(); }

  // Robot `robot`'s observation: its body's network's inputs with a controller per body.
  [[nodiscard]] std::vector<std::string> observation_names(std::size_t robot = 0) const;
  [[nodiscard]] pybind11::tuple observation_bounds(std::size_t robot = 0) const;   // (low, high)
  [[nodiscard]] pybind11::tuple action_bounds() const;        // (low, high)
  [[nodiscard]] std::size_t action_size() const noexcept { return action_size_; }
  [[nodiscard]] std::uint64_t seed() const noexcept { return seed_; }
  [[nodiscard]] int episodes() const noexcept { return episodes_; }
  [[nodiscard]] std::vector<std::string> choices() const;
  [[nodiscard]] const eval::ExperimentSpec& spec() const noexcept { return *spec_; }

 private:
  void begin(std::optional<std::uint64_t> seed);
  // Every robot's action turned into its command, then the step: its outcome, and whether the
  // epoch's steps ran out (the episode ends on either).
  struct Advanced {
    eval::StepOutcome outcome;
    bool truncated = false;
  };
  Advanced advance(std::span<const Action> actions);
  // Every robot's observation and info, as lists in robot order.
  [[nodiscard]] pybind11::tuple every_robot() const;
  [[nodiscard]] pybind11::array_t<double> observation(std::size_t robot = 0) const;
  [[nodiscard]] pybind11::dict info(std::size_t robot = 0) const;
  void require_alone(const char* call) const;
  // Robot `robot`'s network: the controller's, or its body's with a controller per body.
  [[nodiscard]] const control::ControllerSpec& network_of(std::size_t robot) const;
  void check_robot(std::size_t robot) const;

  std::shared_ptr<const CompiledScript> script_;   // holds spec_ and controller_
  const eval::ExperimentSpec* spec_;
  const control::ControllerSpec* controller_ = nullptr;   // none: the action is the wheel commands
  std::vector<std::vector<expr::Slot>> observed_;   // each robot's
  std::size_t action_size_ = 2;
  // The controller's head of each robot, run on the actions; its network is never run, so its
  // weights are zeros of the right size (which it points into).
  std::vector<double> unused_weights_;
  std::vector<std::unique_ptr<control::Controller>> heads_;
  sim::World world_;
  eval::EpochStepper stepper_;
  std::uint64_t seed_;
  int next_epoch_ = 0;
  int episodes_ = 0;
  bool running_ = false;   // an episode has begun and not ended
  double fitness_ = 0.0;   // this episode's step terms, summed as the evaluator sums them
  // Each robot's command and controller's choice on the last step (-1: none), and that
  // choice's experiment-wide id.
  std::vector<control::WheelCommand> commands_;
  std::vector<int> actions_;
  std::vector<int> acting_;
};

}  // namespace esc::python
