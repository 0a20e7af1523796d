// A stored genome's network as a policy for Env: its inputs (Env's observation) in, its
// activated outputs (Env's action) out, with the network's recurrent state kept between
// calls. The network is the one a controller runs (control::Mlp with the head's activation),
// fed the same doubles from the observation, so Env driven by it steps as esc's evaluation
// of the genome does.
#include <memory>
#include <string>
#include <vector>

#include <pybind11/numpy.h>

#include "python/src/bindings.hpp"
#include "python/src/compiled_script.hpp"
#include "runtime/control/controller.hpp"
#include "runtime/control/mlp.hpp"

namespace esc::python {

namespace py = pybind11;

namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

const control::ControllerSpec& network(const CompiledScript& script, const std::string& experiment,
                                       const std::string& controller) {
  const control::ControllerSpec& c = find_controller(find_experiment(script, experiment), controller);
  if (c.is_tree()) throw py::value_error("`" + c.name + "` is a tree controller: a policy is a network's");
  if (c.is_graph())
    throw py::value_error("`" + c.name + "` is a NEAT network: a policy is a fixed network's weights; evaluate NEAT " +
                          "genomes with esc.evaluate, or drive esc.Env with your own outputs");
  return c;
}

std::vector<double> weights(const control::ControllerSpec& c, const Array& genome) {
  if (genome.ndim() != 1 || static_cast<std::size_t>(genome.size()) != c.genome_size())
    throw py::value_error("controller `" + c.name + "` (" + c.architecture() + ") has genomes of " +
                          std::to_string(c.genome_size()) + " weights, but the genome given has " +
                          std::to_string(genome.size()));
  return {genome.data(), genome.data() + genome.size()};
}

class Policy {
 public:
  Policy(const std::shared_ptr<CompiledScript>& script, const std::string& experiment, const std::string& controller,
         const Array& genome)
      : script_(script),
        controller_(&network(*script, experiment, controller)),
        genome_(weights(*controller_, genome)),
        net_(controller_->mlp, controller_->output_count(), control::output_activation(controller_->head), genome_) {}
  Policy(const Policy&) = delete;
  Policy& operator=(const Policy&) = delete;

  py::array_t<double> operator()(const Array& observation) {
    const auto& inputs = controller_->mlp.inputs;
    if (observation.ndim() != 1 || static_cast<std::size_t>(observation.size()) != inputs.size())
      throw py::value_error("the observation of `" + controller_->name + "` is its network's " +
                            std::to_string(inputs.size()) + " inputs, got " + std::to_string(observation.size()) +
                            " values");
    for (std::size_t i = 0; i < inputs.size(); ++i) frame_[inputs[i]] = observation.data()[i];
    net_.forward(frame_);
    py::array_t<double> out(static_cast<py::ssize_t>(net_.output_count()));
    auto o = out.mutable_unchecked<1>();
    for (std::size_t i = 0; i < net_.output_count(); ++i) o(static_cast<py::ssize_t>(i)) = net_.output(i);
    return out;
  }

  // Zeroes an Elman network's context: the start of an epoch.
  void reset() noexcept { net_.reset(); }

 private:
  std::shared_ptr<const CompiledScript> script_;   // holds controller_
  const control::ControllerSpec* controller_;
  std::vector<double> genome_;                     // the network points into it
  control::Mlp net_;
  expr::Frame frame_{};                            // the observation at the network's input slots
};

}  // namespace

void bind_policy(py::module_& m) {
  py::class_<Policy>(m, "Policy", "A genome's network as Env's policy (see esc.Env.policy, which wraps it).")
      .def(py::init<const std::shared_ptr<CompiledScript>&, const std::string&, const std::string&, const Array&>(),
           py::arg("script"), py::arg("experiment"), py::arg("controller"), py::arg("genome"))
      .def("__call__", &Policy::operator(), py::arg("observation"),
           "The network's activated outputs for `observation`, its inputs; advances a recurrent network's state.")
      .def("reset", &Policy::reset, "Zeroes a recurrent network's state, as at the start of an epoch.");
}

}  // namespace esc::python
