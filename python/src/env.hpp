#pragma once
// An experiment's epochs stepped from Python, Gymnasium's way: reset() starts an episode, one
// epoch; step(action) is one control step of it (eval::EpochStepper, the evaluator's own step
// code). Episode k after reset(seed=S) is epoch k of the evaluation with seed S: the same
// start pose, noise and `epoch` observable as that epoch of esc's evaluation.
//
// Without a controller, the action is the two wheel commands in [-1, 1] and the observation
// the robot's senses: ir[0..7], light[0..7], energy. With a network controller, the
// observation is its network's inputs and the action its network's activated outputs, which
// the controller's head turns into wheel commands as in a run (argmax over actions with their
// parameters, or over supervised behaviors); Policy (policy.hpp) computes them from a genome.
#include <cstdint>
#include <memory>
#include <optional>
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

  // The next episode, or epoch 0 of the evaluation with `seed` when one is given:
  // (observation, info).
  pybind11::tuple reset(std::optional<std::uint64_t> seed);
  // (observation, reward, terminated, truncated, info).
  pybind11::tuple step(const pybind11::array_t<double, pybind11::array::c_style | pybind11::array::forcecast>& action);
  // The robot after the last step as a replay records it.
  [[nodiscard]] pybind11::dict state() const;

  [[nodiscard]] std::vector<std::string> observation_names() const;
  [[nodiscard]] pybind11::tuple observation_bounds() const;   // (low, high)
  [[nodiscard]] pybind11::tuple action_bounds() const;        // (low, high)
  [[nodiscard]] std::size_t action_size() const noexcept { return action_size_; }
  [[nodiscard]] std::uint64_t seed() const noexcept { return seed_; }
  [[nodiscard]] int episodes() const noexcept { return episodes_; }
  [[nodiscard]] std::vector<std::string> choices() const;
  [[nodiscard]] const eval::ExperimentSpec& spec() const noexcept { return *spec_; }

 private:
  [[nodiscard]] pybind11::array_t<double> observation() const;
  [[nodiscard]] pybind11::dict info() const;

  std::shared_ptr<const CompiledScript> script_;   // holds spec_ and controller_
  const eval::ExperimentSpec* spec_;
  const control::ControllerSpec* controller_ = nullptr;   // none: the action is the wheel commands
  std::vector<expr::Slot> observed_;
  std::size_t action_size_ = 2;
  // The controller's head, run on the actions; its network is never run, so its weights are
  // zeros of the right size (which it points into).
  std::vector<double> unused_weights_;
  std::unique_ptr<control::Controller> head_;
  sim::World world_;
  eval::EpochStepper stepper_;
  std::uint64_t seed_;
  int next_epoch_ = 0;
  int episodes_ = 0;
  bool running_ = false;   // an episode has begun and not ended
  double fitness_ = 0.0;   // this episode's step terms, summed as the evaluator sums them
  control::WheelCommand command_{};
  int action_ = -1;        // the controller's choice on the last step (-1: none)
};

}  // namespace esc::python
