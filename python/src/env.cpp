#include "python/src/env.hpp"

#include <stdexcept>

#include <pybind11/stl.h>

#include "python/src/bindings.hpp"
#include "python/src/observation.hpp"
#include "runtime/eval/observe.hpp"
#include "runtime/genome/graph/codec.hpp"
#include "runtime/tree_control/tree_driver.hpp"

namespace esc::python {

namespace py = pybind11;

namespace {

using Action = py::array_t<double, py::array::c_style | py::array::forcecast>;

// What the robot senses, the observation without a controller: the IR and light sensors,
// rangefinders, goal radars, ground sensors and bumpers it declares, and the accumulator.
std::vector<expr::Slot> senses(const sim::RobotParams& robot) {
  std::vector<expr::Slot> slots;
  const auto add = [&](expr::Slot first, std::size_t count) {
    for (expr::Slot i = 0; i < count; ++i) slots.push_back(first + i);
  };
  add(expr::slot::ir, robot.ir.mounts.size());
  add(expr::slot::light, robot.ir.mounts.size());
  add(expr::slot::range, robot.rangefinders.angles_rad.size());
  add(expr::slot::radar, static_cast<std::size_t>(robot.radars));
  add(expr::slot::ground_sensor, robot.ground.mounts.size());
  add(expr::slot::bumper, robot.bumpers.size());
  slots.push_back(expr::slot::energy);
  return slots;
}

// A group's Env is PettingZoo's parallel one, keyed by robot (docs/groups.md): not built yet.
const eval::ExperimentSpec& one_robot(const eval::ExperimentSpec& spec) {
  if (spec.robots > 1)
    throw py::value_error("experiment `" + spec.name + "` has a group of " + std::to_string(spec.robots) +
                          " robots: Env drives one robot (a group's multi-agent Env is not built yet); "
                          "esc.evaluate evaluates a group");
  return spec;
}

const control::ControllerSpec* network_controller(const eval::ExperimentSpec& spec,
                                                  const std::optional<std::string>& name) {
  if (!name) return nullptr;
  const control::ControllerSpec& c = find_controller(spec, *name);
  if (c.is_tree())
    throw py::value_error("`" + c.name + "` is a tree controller: Env's actions are a network's outputs; evaluate "
                          "trees with esc.evaluate, or drive the wheels yourself with controller=None");
  return &c;
}

// What the stepper writes only when read (`noise`, the group's observables), as the evaluator's.
eval::StepperReads reads_of(const eval::ExperimentSpec& spec, const control::ControllerSpec* controller) {
  return eval::stepper_reads(spec, controller != nullptr ? *controller : control::ControllerSpec{});
}

py::array_t<double> array_of(const std::vector<double>& v) {
  return py::array_t<double>(static_cast<py::ssize_t>(v.size()), v.data());
}

}  // namespace

Env::Env(const std::shared_ptr<CompiledScript>& script, const std::string& experiment,
         const std::optional<std::string>& controller, std::uint64_t seed)
    : script_(script),
      spec_(&one_robot(find_experiment(*script, experiment))),
      controller_(network_controller(*spec_, controller)),
      observed_(controller_ != nullptr ? controller_->mlp.inputs : senses(spec_->robot)),
      world_(spec_->arena, spec_->robot),
      stepper_(*spec_, world_, reads_of(*spec_, controller_)),
      seed_(seed) {
  if (controller_ == nullptr) return;
  action_size_ = static_cast<std::size_t>(controller_->output_count());
  // The head alone acts on the actions (act()): its network is never run, so any genome of
  // its shape builds it, a NEAT network's minimal one.
  if (controller_->is_graph())
    unused_weights_ = genome::graph::encode(genome::graph::minimal_graph(
        controller_->mlp.inputs.size(), static_cast<std::size_t>(controller_->output_count()),
        genome::graph::Activation::Tanh));
  else
    unused_weights_.assign(controller_->genome_size(), 0.0);
  head_ = std::make_unique<control::Controller>(*controller_, unused_weights_, &tree_control::make_actor);
}

py::tuple Env::reset(std::optional<std::uint64_t> seed) {
  if (seed) {
    seed_ = *seed;
    next_epoch_ = 0;
  }
  stepper_.begin(seed_, next_epoch_++);
  if (head_) head_->reset();
  ++episodes_;
  running_ = true;
  fitness_ = 0.0;
  command_ = {};
  action_ = -1;
  stepper_.observe();
  return py::make_tuple(observation(), info());
}

py::tuple Env::step(const Action& action) {
  if (!running_)
    throw std::runtime_error(episodes_ == 0 ? "call reset() before step()" : "the episode has ended: call reset()");
  if (action.ndim() != 1 || static_cast<std::size_t>(action.size()) != action_size_)
    throw py::value_error("the action is " + std::to_string(action_size_) + " values (" +
                          (controller_ != nullptr ? "the outputs of " + controller_->name + "'s network"
                                                  : std::string("the left and right wheel commands")) +
                          "), got " + std::to_string(action.size()) + " in " + std::to_string(action.ndim()) +
                          " dimension(s)");
  const std::span<const double> a(action.data(), action_size_);
  if (head_) {
    command_ = head_->act(a, stepper_.frame());
    action_ = head_->last_action();
  } else {
    command_ = {a[0], a[1]};
  }
  const eval::StepOutcome outcome =
      stepper_.act(command_, controller_ != nullptr ? controller_->choice_id(action_) : -1);
  fitness_ = eval::add_fitness(fitness_, outcome.term);
  const bool truncated = !outcome.stop && stepper_.steps_taken() >= spec_->steps;
  running_ = !outcome.stop && !truncated;
  stepper_.observe();
  return py::make_tuple(observation(), outcome.term, outcome.stop, truncated, info());
}

py::array_t<double> Env::observation() const {
  py::array_t<double> obs(static_cast<py::ssize_t>(observed_.size()));
  auto out = obs.mutable_unchecked<1>();
  for (std::size_t i = 0; i < observed_.size(); ++i) out(static_cast<py::ssize_t>(i)) = stepper_.frame()[observed_[i]];
  return obs;
}

py::dict Env::info() const {
  py::dict d;
  d["epoch"] = stepper_.epoch();
  d["step"] = stepper_.steps_taken();
  d["fitness"] = fitness_;
  d["action"] = action_;
  return d;
}

py::dict Env::state() const {
  const eval::TraceStep t = stepper_.traced(command_, action_, fitness_);
  py::dict d = info();
  d["x"] = t.pose.x_m;
  d["y"] = t.pose.y_m;
  d["heading"] = t.pose.heading_rad;
  d["left_command"] = t.left_command;
  d["right_command"] = t.right_command;
  d["left_speed"] = t.left_speed_mps;
  d["right_speed"] = t.right_speed_mps;
  d["ir"] = array_of({t.ir.begin(), t.ir.end()});
  d["light"] = array_of({t.light.begin(), t.light.end()});
  d["range"] = array_of({t.range.begin(), t.range.begin() + static_cast<std::ptrdiff_t>(t.range_count)});
  d["radar"] = array_of({t.radar.begin(), t.radar.begin() + static_cast<std::ptrdiff_t>(t.radar_count)});
  d["ground_sensor"] = array_of({t.ground.begin(), t.ground.begin() + static_cast<std::ptrdiff_t>(t.ground_count)});
  d["bumper"] = array_of({t.bumper.begin(), t.bumper.begin() + static_cast<std::ptrdiff_t>(t.bumper_count)});
  d["energy"] = t.energy;
  d["collided"] = t.collided;
  return d;
}

std::vector<std::string> Env::observation_names() const {
  std::vector<std::string> names;
  for (const expr::Slot s : observed_) names.push_back(slot_name(s, spec_->robot));
  return names;
}

py::tuple Env::observation_bounds() const {
  std::vector<double> low, high;
  for (const expr::Slot s : observed_) {
    const SlotRange r = slot_range(s, *spec_);
    low.push_back(r.low);
    high.push_back(r.high);
  }
  return py::make_tuple(array_of(low), array_of(high));
}

py::tuple Env::action_bounds() const {
  // Wheel commands and the classical head's tanh outputs lie in [-1, 1], the logistic outputs
  // of the other heads in [0, 1].
  const bool wheels = controller_ == nullptr || controller_->head == control::Head::Classical;
  return py::make_tuple(array_of(std::vector<double>(action_size_, wheels ? -1.0 : 0.0)),
                        array_of(std::vector<double>(action_size_, 1.0)));
}

std::vector<std::string> Env::choices() const {
  return controller_ != nullptr ? controller_->choice_names() : std::vector<std::string>{};
}

void bind_env(py::module_& m) {
  py::class_<Env>(m, "Env", "One epoch at a time of an experiment, stepped (see esc.Env, which wraps it).")
      .def(py::init<const std::shared_ptr<CompiledScript>&, const std::string&, const std::optional<std::string>&,
                    std::uint64_t>(),
           py::arg("script"), py::arg("experiment"), py::arg("controller"), py::arg("seed"))
      .def("reset", &Env::reset, py::arg("seed") = py::none(),
           "Starts the next episode (epoch k of the evaluation with the current seed), or epoch 0 of `seed`: "
           "(observation, info).")
      .def("step", &Env::step, py::arg("action"), "One control step: (observation, reward, terminated, truncated, info).")
      .def("state", &Env::state, "The robot after the last step, as `esc replay` records it.")
      .def_property_readonly("observation_names", &Env::observation_names)
      .def_property_readonly("observation_bounds", &Env::observation_bounds)
      .def_property_readonly("action_bounds", &Env::action_bounds)
      .def_property_readonly("seed", &Env::seed)
      .def_property_readonly("episodes", &Env::episodes)
      .def_property_readonly("choices", &Env::choices)
      .def_property_readonly("steps", [](const Env& e) { return e.spec().steps; })
      .def_property_readonly("epochs", [](const Env& e) { return e.spec().epochs; });
}

}  // namespace esc::python
