// A run directory read once, from a copy of its database (app::read_untouched): reading
// never changes a byte of it, a killed run's log included, and works on a read-only
// directory. Its tables are the CSV text `esc export DIR --table NAME --format csv` writes,
// made by the same functions; the package parses them with pandas.
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "app/campaign_results.hpp"
#include "app/import_path.hpp"
#include "app/results.hpp"
#include "app/stored_run.hpp"
#include "compiler/names.hpp"
#include "python/src/bindings.hpp"
#include "runtime/control/graph_architecture.hpp"

namespace esc::python {

namespace py = pybind11;

namespace {

// A damaged log's warning as `esc export` says it, to the logger the esc program's other
// lines go to.
class LoggedWarnings final : public app::Events {
 public:
  void note(const app::Note& note) override {
    if (note.kind == app::Note::Kind::Warning)
      py::module_::import("logging").attr("getLogger")("esc").attr("warning")(note.text);
  }
};

class StoredRun {
 public:
  explicit StoredRun(const std::filesystem::path& dir) {
    LoggedWarnings warnings;
    dir_ = app::read_untouched(dir, warnings);
  }

  // std::invalid_argument (a ValueError) for an unknown table, naming the nearest. The
  // standard library, when given, compiles the run's stored sources where the topology table
  // needs them (a front's or archive's NEAT networks), as `esc export` does.
  [[nodiscard]] std::string table_csv(const std::string& name, const std::filesystem::path& standard_library) const {
    const std::string table = name.empty() ? std::string("generations") : name;
    if (standard_library.empty()) return app::table_text({dir_}, table, true);
    const compiler::CompileOptions options = app::compile_options(standard_library);
    return app::table_text({dir_}, table, true, &options);
  }

  // The study's name, or "" for a plain experiment.
  [[nodiscard]] std::string study() const {
    const auto& all = dir_.experiments;
    return !all.empty() && all.front().condition ? all.front().condition->study : std::string();
  }

  [[nodiscard]] std::vector<std::string> experiments() const {
    std::vector<std::string> names;
    for (const store::StoredExperiment& e : dir_.experiments) names.push_back(e.name);
    return names;
  }

  [[nodiscard]] std::vector<std::string> conditions() const {
    std::vector<std::string> names;
    for (const store::StoredExperiment& e : dir_.experiments)
      if (e.condition) names.push_back(e.condition->name);
    return names;
  }

  // Every controller of every experiment (condition), each named once, in order.
  [[nodiscard]] std::vector<std::string> controllers() const {
    std::vector<std::string> names;
    for (const store::StoredExperiment& e : dir_.experiments)
      for (const store::StoredController& c : e.controllers)
        if (std::find(names.begin(), names.end(), c.name) == names.end()) names.push_back(c.name);
    return names;
  }

  // What run `run` (from 1) of `controller` kept beside its best after its last generation:
  // its front or archive, each member with its genome and, where the state records it, the
  // evaluation that measured it. The experiment is compiled from the run's stored sources.
  [[nodiscard]] py::list members(const std::string& controller, int run, const std::string& condition,
                                 const std::filesystem::path& standard_library) const {
    const store::StoredExperiment& e = find_experiment(condition);
    const store::StoredController& c = find_controller(e, controller);
    const app::StoredRun stored{&e, dir_.path, dir_.path};
    app::Events quiet;   // the script's warnings were the run's, given when it ran
    const eval::ExperimentSpec spec = app::experiment_of_run(stored, app::compile_options(standard_library), quiet);
    const evo::Members kept = app::final_members(stored, spec, c.name, run - 1);
    const eval::RunResult& result = *app::finished_run(stored, c.name, run - 1).run;
    // Named as the front and archive tables name them, a minimised objective not negated.
    const auto layout = eval::member_layout(spec, kept);
    py::list out;
    for (const evo::Member& m : kept.members) {
      py::dict objectives;
      for (std::size_t i = 0; i < m.objectives.size() && i < layout->objectives.size(); ++i)
        objectives[py::str(layout->objectives[i])] = layout->minimized[i] ? -m.objectives[i] : m.objectives[i];
      py::dict d;
      d["kind"] = kept.kind == evo::MemberKind::Front ? "front" : "archive";
      d["cell"] = m.cell;
      d["objectives"] = objectives;
      d["descriptors"] = py::array_t<double>(static_cast<py::ssize_t>(m.descriptors.size()), m.descriptors.data());
      d["genome"] = py::array_t<double>(static_cast<py::ssize_t>(m.genome.size()), m.genome.data());
      d["graph"] = !m.genome.empty() && control::is_graph_architecture(c.architecture);
      const bool known = m.measured.known();
      d["generation"] = known ? py::object(py::int_(m.measured.generation)) : py::object(py::none());
      d["candidate"] = known ? py::object(py::int_(m.measured.candidate)) : py::object(py::none());
      d["evaluation_seed"] =
          known ? py::object(py::int_(eval::evaluation_seed_of(result.seed, m.measured))) : py::object(py::none());
      out.append(d);
    }
    return out;
  }

  // The runs of each controller of the experiment, or of a study's condition `condition`.
  [[nodiscard]] int runs(const std::string& condition) const { return find_experiment(condition).runs; }

  // Run `run` (from 1) of `controller`: its best genome and where its best evaluation happened.
  [[nodiscard]] py::dict best(const std::string& controller, int run, const std::string& condition) const {
    const store::StoredController& c = find_controller(find_experiment(condition), controller);
    const auto r = std::find_if(c.finished.begin(), c.finished.end(),
                                [run](const eval::RunResult& x) { return x.run + 1 == run; });
    if (r == c.finished.end())
      throw py::value_error("controller " + c.name + " has no finished run " + std::to_string(run) + " (" +
                            std::to_string(c.finished.size()) + " finished)");
    py::dict d;
    d["run"] = r->run + 1;
    d["run_seed"] = r->seed;
    d["fitness"] = r->best_fitness;
    d["generation"] = r->best_generation;
    d["individual"] = r->best_index;
    d["evaluation_seed"] = eval::evaluation_seed(r->seed, r->best_generation, static_cast<std::size_t>(r->best_index));
    d["genome"] = py::array_t<double>(static_cast<py::ssize_t>(r->best_genome.size()), r->best_genome.data());
    d["tree"] = c.head == "tree" ? py::object(py::str(r->best_tree)) : py::object(py::none());
    d["graph"] = control::is_graph_architecture(c.architecture);
    return d;
  }

 private:
  // The experiment, or a study's condition `condition` ("" when the study has only one).
  [[nodiscard]] const store::StoredExperiment& find_experiment(const std::string& condition) const {
    const std::vector<std::string> names = conditions();
    if (names.empty()) {
      if (!condition.empty()) throw py::value_error(dir_.path.string() + " holds an experiment, not a study: it has no conditions");
      return dir_.experiments.front();
    }
    if (condition.empty() && names.size() == 1) return dir_.experiments.front();
    for (const store::StoredExperiment& e : dir_.experiments)
      if (e.condition && e.condition->name == condition) return e;
    std::string message = condition.empty() ? dir_.path.string() + " holds study `" + study() + "`: name a condition"
                                            : dir_.path.string() + " has no condition `" + condition + "`";
    message += "; its conditions are " + compiler::quoted_list(names, " and ");
    if (const auto near = compiler::closest(condition, names); near && !condition.empty())
      message += "; did you mean `" + *near + "`?";
    throw py::value_error(message);
  }

  [[nodiscard]] static const store::StoredController& find_controller(const store::StoredExperiment& e,
                                                                      const std::string& name) {
    std::vector<std::string> names;
    for (const store::StoredController& c : e.controllers) {
      if (c.name == name) return c;
      names.push_back(c.name);
    }
    std::string message = "experiment `" + e.name + "` stored no controller `" + name + "`; it compares " +
                          compiler::quoted_list(names, " and ");
    if (const auto near = compiler::closest(name, names)) message += "; did you mean `" + *near + "`?";
    throw py::value_error(message);
  }

  store::StoredDirectory dir_;
};

}  // namespace

void bind_results(py::module_& m) {
  py::class_<StoredRun>(m, "StoredRun", "A run directory as stored (see esc.Run, which wraps it).")
      .def(py::init<const std::filesystem::path&>(), py::arg("directory"),
           "Reads `directory`'s database from a copy, changing nothing in it. Raises esc.Error when it is not an "
           "esc run directory, is damaged, or holds no committed generation.")
      .def("table_csv", &StoredRun::table_csv, py::arg("name"),
           py::arg("standard_library") = std::filesystem::path(),
           "The table `name` as `esc export DIR --table NAME --format csv` writes it; the topology table's fronts "
           "and archives need `standard_library` (without it, each run's best alone).")
      .def_property_readonly("study", &StoredRun::study, "The study's name, or an empty string for an experiment.")
      .def_property_readonly("experiments", &StoredRun::experiments,
                             "The experiments stored: one, or one per condition of a study.")
      .def_property_readonly("conditions", &StoredRun::conditions, "A study's conditions in its order; empty for an experiment.")
      .def_property_readonly("controllers", &StoredRun::controllers, "The controllers compared, in order.")
      .def("best", &StoredRun::best, py::arg("controller"), py::arg("run"), py::arg("condition") = "",
           "Finished run `run` (from 1) of `controller`: a dict of run, run_seed, fitness, generation, individual, "
           "evaluation_seed, genome (network weights, or a tree encoded) and tree (a tree's text, else None).")
      .def("runs", &StoredRun::runs, py::arg("condition") = "",
           "The runs of each controller of the experiment (or of a study's `condition`), finished or not.")
      .def("members", &StoredRun::members, py::arg("controller"), py::arg("run"), py::arg("condition"),
           py::arg("standard_library"),
           "The final front or archive of finished run `run` (from 1) of `controller`: a list of dicts of kind, "
           "cell, objectives, descriptors, genome, generation, candidate and evaluation_seed (None where the "
           "state does not record them).");
}

}  // namespace esc::python
