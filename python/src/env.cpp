#include "python/src/env.hpp"

#include <algorithm>
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

using Action = Env::Action;

const control::ControllerSpec* network_controller(const eval::ExperimentSpec& spec,
                                                  const std::optional<std::string>& name) {
  if (!name) return nullptr;
  const control::ControllerSpec& c = find_controller(spec, *name);
  if (c.is_tree())
    throw py::value_error("`" + c.name + "` is a tree controller: Env's actions are a network's outputs; evaluate "
                          "trees with esc.evaluate, or drive the wheels yourself with controller=None");
  return &c;
}

// What the stepper writes only when read (`noise`, the group's observables), as the evaluator's;
// a group's every observable, as its replay records them (state() gives them).
eval::StepperReads reads_of(const eval::ExperimentSpec& spec, const control::ControllerSpec* controller) {
  eval::StepperReads reads = eval::stepper_reads(spec, controller != nullptr ? *controller : control::ControllerSpec{});
  if (spec.robots > 1) reads.pairs = true;
  return reads;
}

py::array_t<double> array_of(const std::vector<double>& v) {
  return py::array_t<double>(static_cast<py::ssize_t>(v.size()), v.data());
}

}  // namespace

Env::Env(const std::shared_ptr<CompiledScript>& script, const std::string& experiment,
         const std::optional<std::string>& controller, std::uint64_t seed)
    : script_(script),
      spec_(&find_experiment(*script, experiment)),
      controller_(network_controller(*spec_, controller)),
      world_(eval::world_of(*spec_)),
      stepper_(*spec_, world_, reads_of(*spec_, controller_)),
      seed_(seed),
      commands_(stepper_.robots()),
      actions_(stepper_.robots(), -1),
      acting_(stepper_.robots(), -1) {
  const std::vector<sim::RobotParams> bodies = spec_->robot_params();
  for (std::size_t i = 0; i < stepper_.robots(); ++i)
    observed_.push_back(controller_ != nullptr ? network_of(i).mlp.inputs : senses(bodies[i]));
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
  // A controller per body's networks share the head: each robot's is its body's network's.
  for (std::size_t i = 0; i < stepper_.robots(); ++i) {
    const control::ControllerSpec& network = network_of(i);
    const std::span<const double> weights(unused_weights_);
    heads_.push_back(std::make_unique<control::Controller>(
        network, controller_->per_body() ? weights.first(network.genome_size()) : weights, &tree_control::make_actor));
  }
}

const control::ControllerSpec& Env::network_of(std::size_t robot) const {
  if (!controller_->per_body()) return *controller_;
  return controller_->networks.at(controller_->body_networks.at(spec_->body_of(robot)));
}

void Env::check_robot(std::size_t robot) const {
  if (robot >= robots())
    throw py::value_error("the experiment has " + std::to_string(robots()) + " robots; there is no robot " +
                          std::to_string(robot + 1));
}

void Env::require_alone(const char* call) const {
  if (robots() > 1)
    throw py::value_error("experiment `" + spec_->name + "` has a group of " + std::to_string(robots()) +
                          " robots: " + call + " drives a robot alone; step the group with esc.ParallelEnv "
                          "(PettingZoo's parallel API), or evaluate it with esc.evaluate");
}

void Env::begin(std::optional<std::uint64_t> seed) {
  if (seed) {
    seed_ = *seed;
    next_epoch_ = 0;
  }
  stepper_.begin(seed_, next_epoch_++);
  for (const auto& head : heads_) head->reset();
  ++episodes_;
  running_ = true;
  fitness_ = 0.0;
  std::fill(commands_.begin(), commands_.end(), control::WheelCommand{});
  std::fill(actions_.begin(), actions_.end(), -1);
  stepper_.observe();
}

Env::Advanced Env::advance(std::span<const Action> actions) {
  if (!running_)
    throw std::runtime_error(episodes_ == 0 ? "call reset() before step()" : "the episode has ended: call reset()");
  // Every action checked before any robot acts: a refused step changes nothing.
  for (std::size_t i = 0; i < actions.size(); ++i) {
    const Action& action = actions[i];
    if (action.ndim() != 1 || static_cast<std::size_t>(action.size()) != action_size_)
      throw py::value_error(std::string(robots() > 1 ? "robot " + std::to_string(i + 1) + "'s action" : "the action") +
                            " is " + std::to_string(action_size_) + " values (" +
                            (controller_ != nullptr ? "the outputs of " + controller_->name + "'s network"
                                                    : std::string("the left and right wheel commands")) +
                            "), got " + std::to_string(action.size()) + " in " + std::to_string(action.ndim()) +
                            " dimension(s)");
  }
  for (std::size_t i = 0; i < actions.size(); ++i) {
    const std::span<const double> a(actions[i].data(), action_size_);
    if (!heads_.empty()) {
      commands_[i] = heads_[i]->act(a, stepper_.frame(i));
      actions_[i] = heads_[i]->last_action();
    } else {
      commands_[i] = {a[0], a[1]};
    }
    acting_[i] = controller_ != nullptr ? controller_->choice_id(actions_[i]) : -1;
  }
  const eval::StepOutcome outcome = stepper_.act(commands_, acting_);
  fitness_ = eval::add_fitness(fitness_, outcome.term);
  const bool truncated = !outcome.stop && stepper_.steps_taken() >= spec_->steps;
  running_ = !outcome.stop && !truncated;
  return {outcome, truncated};
}

py::tuple Env::every_robot() const {
  py::list observations, infos;
  for (std::size_t i = 0; i < robots(); ++i) {
    observations.append(observation(i));
    infos.append(info(i));
  }
  return py::make_tuple(observations, infos);
}

py::tuple Env::reset(std::optional<std::uint64_t> seed) {
  require_alone("Env");
  begin(seed);
  return py::make_tuple(observation(), info());
}

py::tuple Env::step(const Action& action) {
  require_alone("Env");
  const auto [outcome, truncated] = advance(std::span<const Action>(&action, 1));
  stepper_.observe();
  return py::make_tuple(observation(), outcome.term, outcome.stop, truncated, info());
}

py::tuple Env::reset_group(std::optional<std::uint64_t> seed) {
  begin(seed);
  return every_robot();
}

py::tuple Env::step_group(const std::vector<Action>& actions) {
  if (actions.size() != robots())
    throw py::value_error("the group has " + std::to_string(robots()) + " robots, but " +
                          std::to_string(actions.size()) + " actions were given");
  const auto [outcome, truncated] = advance(actions);
  py::list rewards;   // read before observe() moves the clock on
  for (std::size_t i = 0; i < robots(); ++i) rewards.append(stepper_.term(i));
  stepper_.observe();
  const py::tuple robots_now = every_robot();
  return py::make_tuple(robots_now[0], rewards, outcome.stop, truncated, robots_now[1]);
}

py::array_t<double> Env::observation(std::size_t robot) const {
  const std::vector<expr::Slot>& observed = observed_[robot];
  py::array_t<double> obs(static_cast<py::ssize_t>(observed.size()));
  auto out = obs.mutable_unchecked<1>();
  for (std::size_t i = 0; i < observed.size(); ++i)
    out(static_cast<py::ssize_t>(i)) = stepper_.frame(robot)[observed[i]];
  return obs;
}

py::dict Env::info(std::size_t robot) const {
  py::dict d;
  d["epoch"] = stepper_.epoch();
  d["step"] = stepper_.steps_taken();
  d["fitness"] = fitness_;
  d["action"] = actions_[robot];
  return d;
}

py::dict Env::state(std::size_t robot) const {
  check_robot(robot);
  const eval::TraceStep t = stepper_.traced(commands_[robot], actions_[robot], fitness_, robot);
  py::dict d = info(robot);
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
  if (t.grouped) {
    for (std::size_t i = 0; i < t.group.size(); ++i) d[py::str(std::string(eval::kTracedGroupNames[i]))] = t.group[i];
  }
  return d;
}

std::vector<std::string> Env::observation_names(std::size_t robot) const {
  check_robot(robot);
  const sim::RobotParams& body = spec_->bodies.empty() ? spec_->robot : spec_->bodies[spec_->body_of(robot)].params;
  std::vector<std::string> names;
  for (const expr::Slot s : observed_[robot]) names.push_back(slot_name(s, body));
  return names;
}

py::tuple Env::observation_bounds(std::size_t robot) const {
  check_robot(robot);
  std::vector<double> low, high;
  for (const expr::Slot s : observed_[robot]) {
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
      .def("state", &Env::state, py::arg("robot") = 0, "Robot `robot` (from 0) after the last step, as `esc replay` "
           "records it.")
      .def("reset_group", &Env::reset_group, py::arg("seed") = py::none(),
           "A group's reset: (observations, infos), lists in robot order.")
      .def("step_group", &Env::step_group, py::arg("actions"),
           "A group's step, an action per robot: (observations, rewards, terminated, truncated, infos).")
      .def_property_readonly("robots", &Env::robots)
      .def("observation_names", &Env::observation_names, py::arg("robot") = 0,
           "What each entry of robot `robot`'s observation is, by observable name.")
      .def("observation_bounds", &Env::observation_bounds, py::arg("robot") = 0,
           "Robot `robot`'s observation bounds: (low, high).")
      .def_property_readonly("action_bounds", &Env::action_bounds)
      .def_property_readonly("seed", &Env::seed)
      .def_property_readonly("episodes", &Env::episodes)
      .def_property_readonly("choices", &Env::choices)
      .def_property_readonly("steps", [](const Env& e) { return e.spec().steps; })
      .def_property_readonly("epochs", [](const Env& e) { return e.spec().epochs; });
}

}  // namespace esc::python
