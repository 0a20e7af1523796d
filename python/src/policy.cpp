// A stored genome's network as a policy for Env: its inputs (Env's observation) in, its
// activated outputs (Env's action) out, with the network's recurrent state kept between
// calls. The network is the one a controller runs (control::Mlp with the head's activation,
// or a NEAT network's control::GraphNet, activated once per call as once per control step),
// fed the same doubles from the observation, so Env driven by it steps as esc's evaluation
// of the genome does.
#include <algorithm>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "python/src/bindings.hpp"
#include "python/src/compiled_script.hpp"
#include "runtime/control/controller.hpp"
#include "runtime/control/graph_net.hpp"
#include "runtime/control/mlp.hpp"

namespace esc::python {

namespace py = pybind11;

namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

const control::ControllerSpec& network(const CompiledScript& script, const std::string& experiment,
                                       const std::string& controller) {
  const control::ControllerSpec& c = find_controller(find_experiment(script, experiment), controller);
  if (c.is_tree()) throw py::value_error("`" + c.name + "` is a tree controller: a policy is a network's");
  return c;
}

// A network's weights (one role's, with `roles` roles), or a NEAT network's graph genome in its
// flat form.
std::vector<double> weights(const control::ControllerSpec& c, const Array& genome, int roles) {
  if (c.is_graph()) {
    const std::span<const double> flat(genome.data(), static_cast<std::size_t>(genome.size()));
    if (genome.ndim() != 1) throw py::value_error("a graph genome is a 1-D array");
    if (std::string why = control::graph_genome_problem(c, flat); !why.empty())
      throw py::value_error("the genome is not a graph genome of `" + c.name + "`: " + why);
    return {flat.begin(), flat.end()};
  }
  if (genome.ndim() != 1 || static_cast<std::size_t>(genome.size()) != c.genome_size())
    throw py::value_error("controller `" + c.name + "` (" + c.architecture() + ") has " +
                          (roles > 1 ? "networks of " + std::to_string(c.genome_size()) + " weights (its genomes hold " +
                                           std::to_string(roles) + " roles' networks: ParallelEnv.policies splits one)"
                                     : "genomes of " + std::to_string(c.genome_size()) + " weights") +
                          ", but the genome given has " + std::to_string(genome.size()));
  return {genome.data(), genome.data() + genome.size()};
}

// A controller per body's network for `body`, its weights the genome's slice for it; any
// other controller itself, its weights the genome (network, weights).
std::pair<const control::ControllerSpec*, std::vector<double>> body_network(const control::ControllerSpec& c,
                                                                            const Array& genome,
                                                                            const std::optional<std::string>& body,
                                                                            int roles) {
  if (!c.per_body()) {
    if (body) throw py::value_error("`" + c.name + "` is one network for every body: give no body");
    return {&c, weights(c, genome, roles)};
  }
  const auto it = body ? std::find(c.network_bodies.begin(), c.network_bodies.end(), *body) : c.network_bodies.end();
  if (it == c.network_bodies.end())
    throw py::value_error("`" + c.name + "` is a controller per body (" + c.architecture() +
                          "): a policy is one body's network; give body= one of " +
                          fmt::format("{}", fmt::join(c.network_bodies, ", ")) + (body ? ", not " + *body : ""));
  const std::vector<double> all = weights(c, genome, roles);
  const auto k = static_cast<std::size_t>(it - c.network_bodies.begin());
  const auto first = all.begin() + static_cast<std::ptrdiff_t>(c.network_offset(k));
  return {&c.networks[k], {first, first + static_cast<std::ptrdiff_t>(c.networks[k].genome_size())}};
}

class Policy {
 public:
  Policy(const std::shared_ptr<CompiledScript>& script, const std::string& experiment, const std::string& controller,
         const Array& genome, const std::optional<std::string>& body)
      : Policy(script, body_network(network(*script, experiment, controller), genome, body,
                                    find_experiment(*script, experiment).roles)) {}
  Policy(const Policy&) = delete;
  Policy& operator=(const Policy&) = delete;

  py::array_t<double> operator()(const Array& observation) {
    const auto& inputs = controller_->mlp.inputs;
    if (observation.ndim() != 1 || static_cast<std::size_t>(observation.size()) != inputs.size())
      throw py::value_error("the observation of `" + controller_->name + "` is its network's " +
                            std::to_string(inputs.size()) + " inputs, got " + std::to_string(observation.size()) +
                            " values");
    for (std::size_t i = 0; i < inputs.size(); ++i) frame_[inputs[i]] = observation.data()[i];
    std::visit([&](auto& net) { net.forward(frame_); }, net_);
    const auto outputs = static_cast<std::size_t>(controller_->output_count());
    py::array_t<double> out(static_cast<py::ssize_t>(outputs));
    auto o = out.mutable_unchecked<1>();
    for (std::size_t i = 0; i < outputs; ++i)
      o(static_cast<py::ssize_t>(i)) = std::visit([i](const auto& net) { return net.output(i); }, net_);
    return out;
  }

  // Zeroes an Elman network's context, or a NEAT network's state: the start of an epoch.
  void reset() noexcept {
    std::visit([](auto& net) { net.reset(); }, net_);
  }

 private:
  Policy(const std::shared_ptr<CompiledScript>& script,
         std::pair<const control::ControllerSpec*, std::vector<double>> network)
      : script_(script),
        controller_(network.first),
        genome_(std::move(network.second)),
        net_(make_net(*controller_, genome_)) {}

  using Net = std::variant<control::Mlp, control::GraphNet>;
  static Net make_net(const control::ControllerSpec& c, const std::vector<double>& genome) {
    if (c.is_graph()) return Net(std::in_place_type<control::GraphNet>, c.mlp, c.output_count(), genome);
    return Net(std::in_place_type<control::Mlp>, c.mlp, c.output_count(), control::output_activation(c.head), genome);
  }

  std::shared_ptr<const CompiledScript> script_;   // holds controller_
  const control::ControllerSpec* controller_;
  std::vector<double> genome_;                     // the network points into it
  Net net_;
  expr::Frame frame_{};                            // the observation at the network's input slots
};

}  // namespace

void bind_policy(py::module_& m) {
  py::class_<Policy>(m, "Policy", "A genome's network as Env's policy (see esc.Env.policy, which wraps it).")
      .def(py::init<const std::shared_ptr<CompiledScript>&, const std::string&, const std::string&, const Array&,
                    const std::optional<std::string>&>(),
           py::arg("script"), py::arg("experiment"), py::arg("controller"), py::arg("genome"),
           py::arg("body") = py::none())
      .def("__call__", &Policy::operator(), py::arg("observation"),
           "The network's activated outputs for `observation`, its inputs; advances a recurrent network's state.")
      .def("reset", &Policy::reset, "Zeroes a recurrent network's state, as at the start of an epoch.");
}

}  // namespace esc::python
