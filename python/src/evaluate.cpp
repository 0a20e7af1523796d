// The fitness (or every objective and descriptor) of many genomes of one controller, each evaluated as a run evaluates an
// individual (eval::Evaluator: the same code, so the same doubles), on every thread while
// Python goes on (the GIL released). Evaluation i draws its start poses and noise from seeds[i]
// alone, so the result does not depend on the threads or the order.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "python/src/bindings.hpp"
#include "python/src/compiled_script.hpp"
#include "runtime/eval/campaign.hpp"
#include "runtime/control/graph_net.hpp"
#include "runtime/eval/evaluator.hpp"
#include "runtime/genome/tree/codec.hpp"

namespace esc::python {

namespace py = pybind11;

namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;
using Seeds = py::array_t<std::uint64_t, py::array::c_style | py::array::forcecast>;

// A network's genomes: the rows of a k x n array, n the controller's genome size.
std::vector<std::vector<double>> network_genomes(const control::ControllerSpec& c, const eval::ExperimentSpec& spec,
                                                 const py::handle& genomes) {
  const auto a = genomes.cast<Array>();
  if (a.ndim() != 2)
    throw py::value_error("genomes of network controller `" + c.name + "` are a 2-D array, one row per genome");
  const auto n = static_cast<std::size_t>(a.shape(1));
  if (n != spec.genome_length(c))
    throw py::value_error("controller `" + c.name + "` (" + c.architecture() + ") of experiment `" + spec.name +
                          "` has genomes of " + std::to_string(spec.genome_length(c)) + " weights" +
                          (spec.roles > 1 ? " (" + std::to_string(spec.roles) + " roles of " +
                                                std::to_string(c.genome_size()) + ")"
                                          : std::string()) +
                          ", but the rows given have " + std::to_string(n));
  std::vector<std::vector<double>> rows(static_cast<std::size_t>(a.shape(0)));
  for (std::size_t i = 0; i < rows.size(); ++i) rows[i].assign(a.data(static_cast<py::ssize_t>(i)), a.data(static_cast<py::ssize_t>(i)) + n);
  return rows;
}

// Genomes of variable length, one 1-D array each: a tree controller's encoded trees
// (runtime/genome/tree/codec.hpp) or a NEAT controller's graph genomes (runtime/genome/graph/
// codec.hpp), checked here, with the GIL held, so that a bad one is a ValueError naming it.
std::vector<std::vector<double>> encoded_genomes(const control::ControllerSpec& c, const py::handle& genomes) {
  std::vector<std::vector<double>> out;
  for (const py::handle& g : genomes) {
    const auto a = g.cast<Array>();
    out.emplace_back(a.data(), a.data() + a.size());
    std::string why;
    if (c.is_tree()) {
      try {
        (void)genome::tree::decode(out.back(), *c.primitives);
      } catch (const std::invalid_argument& e) {
        why = e.what();
      }
    } else {
      why = control::graph_genome_problem(c, out.back());
    }
    if (!why.empty())
      throw py::value_error("genome " + std::to_string(out.size() - 1) + " is not " +
                            (c.is_tree() ? "an encoded tree" : "a graph genome") + " of controller `" + c.name +
                            "`: " + why);
  }
  return out;
}

// Each genome's evaluation, as a run's; the experiment it ran in goes to `spec`.
std::vector<eval::Evaluation> evaluations(const std::shared_ptr<CompiledScript>& script, const std::string& experiment,
                                          const std::string& controller, const py::handle& genomes,
                                          std::optional<int> epochs, const Seeds& seeds, eval::ExperimentSpec& spec) {
  spec = find_experiment(*script, experiment);
  if (epochs)
    if (const std::string error = compiler::apply_setting(spec, "epochs", std::to_string(*epochs)); !error.empty())
      throw py::value_error("epochs=" + std::to_string(*epochs) + ": " + error);
  const control::ControllerSpec& c = find_controller(spec, controller);
  const std::vector<std::vector<double>> rows =
      c.is_tree() || c.is_graph() ? encoded_genomes(c, genomes) : network_genomes(c, spec, genomes);
  if (static_cast<std::size_t>(seeds.size()) != rows.size())
    throw py::value_error(std::to_string(seeds.size()) + " seeds for " + std::to_string(rows.size()) + " genomes");
  const std::span<const std::uint64_t> seed(seeds.data(), rows.size());
  std::vector<eval::Evaluation> out(rows.size());
  {
    const py::gil_scoped_release release;
    tbb::enumerable_thread_specific<eval::Evaluator> evaluators([&spec] { return eval::Evaluator(spec); });
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rows.size()), [&](const tbb::blocked_range<std::size_t>& r) {
      eval::Evaluator& e = evaluators.local();
      for (std::size_t i = r.begin(); i != r.end(); ++i) out[i] = e.evaluate(c, rows[i], seed[i]);
    });
  }
  return out;
}

py::array_t<double> evaluate(const std::shared_ptr<CompiledScript>& script, const std::string& experiment,
                             const std::string& controller, const py::handle& genomes, std::optional<int> epochs,
                             const Seeds& seeds) {
  eval::ExperimentSpec spec;
  const std::vector<eval::Evaluation> all = evaluations(script, experiment, controller, genomes, epochs, seeds, spec);
  py::array_t<double> fitness(static_cast<py::ssize_t>(all.size()));
  for (std::size_t i = 0; i < all.size(); ++i) fitness.mutable_at(static_cast<py::ssize_t>(i)) = all[i].fitness;
  return fitness;
}

// Every objective (the fitness first, as measured) and descriptor of each genome: their
// names, and a row of values per genome.
py::tuple measure(const std::shared_ptr<CompiledScript>& script, const std::string& experiment,
                  const std::string& controller, const py::handle& genomes, std::optional<int> epochs,
                  const Seeds& seeds) {
  eval::ExperimentSpec spec;
  const std::vector<eval::Evaluation> all = evaluations(script, experiment, controller, genomes, epochs, seeds, spec);
  std::vector<std::string> names{spec.fitness.name};
  for (const eval::FitnessSpec& f : spec.further) names.push_back(f.name);
  for (const eval::DescriptorSpec& d : spec.descriptors) names.push_back(d.name);
  py::array_t<double> values({static_cast<py::ssize_t>(all.size()), static_cast<py::ssize_t>(names.size())});
  for (std::size_t i = 0; i < all.size(); ++i) {
    const auto row = static_cast<py::ssize_t>(i);
    py::ssize_t col = 0;
    values.mutable_at(row, col++) = all[i].fitness;
    for (const double v : all[i].objectives) values.mutable_at(row, col++) = v;
    for (const double v : all[i].descriptors) values.mutable_at(row, col++) = v;
  }
  return py::make_tuple(names, values);
}

}  // namespace

void bind_evaluate(py::module_& m) {
  m.def("evaluate", &evaluate, py::arg("script"), py::arg("experiment"), py::arg("controller"), py::arg("genomes"),
        py::arg("epochs"), py::arg("seeds"),
        "The fitness of each genome (rows of a 2-D array for a network, encoded trees for a tree controller, "
        "graph genomes for a NEAT network), "
        "genome i evaluated with evaluation seed seeds[i] over `epochs` epochs (None: the experiment's), as a run "
        "evaluates an individual. On every thread, the GIL released.");
  m.def("measure", &measure, py::arg("script"), py::arg("experiment"), py::arg("controller"), py::arg("genomes"),
        py::arg("epochs"), py::arg("seeds"),
        "As evaluate, every objective (the fitness first, as measured) and descriptor of each genome: (their names, "
        "a 2-D array with a row per genome).");
  m.def("evaluation_seed", &eval::evaluation_seed, py::arg("run_seed"), py::arg("generation"), py::arg("individual"),
        "The evaluation seed of offspring `individual` of generation `generation` of the run seeded `run_seed`.");
  m.def("run_seed", &eval::run_seed, py::arg("master_seed"), py::arg("run"),
        "The seed of run `run` (from 0) of an experiment seeded `master_seed`.");
}

}  // namespace esc::python
