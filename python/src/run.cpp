// esc.run and esc.resume: the application layer's run and resume (app/run.hpp), the GIL
// released while they work. After each generation stored the progress callable is called
// (the GIL taken), then a pending Ctrl-C stops the run there; either's exception leaves a
// directory that esc.resume (or `esc run --resume`) continues.
#include <optional>
#include <string>
#include <vector>

#include <pybind11/functional.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "app/import_path.hpp"
#include "app/run.hpp"
#include "python/src/bindings.hpp"

namespace esc::python {

namespace py = pybind11;

namespace {

class PythonEvents final : public app::Events {
 public:
  explicit PythonEvents(py::object progress) : progress_(std::move(progress)) {}

  void warnings(const compiler::CompileResult& compiled) override {
    const py::gil_scoped_acquire gil;
    const py::object warning = py::module_::import("esc.errors").attr("ScriptWarning");
    const std::string text = compiler::render_all(compiled.diagnostics, compiled.sources, false);
    if (PyErr_WarnEx(warning.ptr(), text.c_str(), 1) != 0) throw py::error_already_set();
  }

  // To the "esc" logger: what the esc program prints as `esc: ...` lines.
  void note(const app::Note& note) override {
    const py::gil_scoped_acquire gil;
    const py::object logger = py::module_::import("logging").attr("getLogger")("esc");
    logger.attr(note.kind == app::Note::Kind::Warning ? "warning" : "info")(note.text);
  }

  std::unique_ptr<app::Progress> progress(const eval::ExperimentSpec&, const std::string& condition,
                                          eval::CampaignListener& next, std::int64_t) override {
    return std::make_unique<Generations>(next, progress_, condition);
  }

 private:
  class Generations final : public app::Progress {
   public:
    Generations(eval::CampaignListener& next, const py::object& callback, std::string condition)
        : Progress(next), callback_(callback), condition_(std::move(condition)) {}

    // Once the directory holds the generation: the progress callable is told of it, then a
    // Ctrl-C pending stops here. An exception either raises stops the run with the
    // generation kept, for esc.resume to continue from.
    void checkpoint(const control::ControllerSpec& c, const eval::RunState& state) override {
      Progress::checkpoint(c, state);
      const py::gil_scoped_acquire gil;
      if (!callback_.is_none()) {
        const eval::GenerationStats& g = state.generations.back();
        const py::object record = py::module_::import("esc.running").attr("Generation");
        callback_(record(condition_, c.name, state.run + 1, g.generation, g.best, g.mean));
      }
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    }

   private:
    const py::object& callback_;
    std::string condition_;
  };

  py::object progress_;
};

// `act` (app::run or app::resume) with the GIL released, its outcome as a dict (dir, study, ran).
template <typename Request>
py::dict outcome_of(app::Outcome (*act)(const Request&, const compiler::CompileOptions&, app::Events&),
                    const Request& r, const std::filesystem::path& standard_library, const py::object& progress) {
  PythonEvents events(progress);
  std::optional<app::Outcome> o;
  {
    const py::gil_scoped_release released;
    o.emplace(act(r, app::compile_options(standard_library), events));
  }
  py::dict d;
  d["dir"] = o->dir.string();
  d["study"] = o->study;
  d["ran"] = o->ran;
  return d;
}

py::dict run(const std::filesystem::path& script, const std::string& experiment, std::optional<int> runs,
             std::optional<int> generations, std::optional<std::uint64_t> seed, int threads,
             const std::filesystem::path& out, const std::vector<std::string>& set,
             const std::vector<std::string>& controllers, const std::filesystem::path& cache,
             const std::filesystem::path& standard_library, const py::object& progress) {
  app::RunRequest r;
  r.script = script;
  r.experiment = experiment;
  r.overrides = {runs, generations, seed, set, controllers, cache};
  r.execution.threads = threads;
  r.out = out;
  return outcome_of(&app::run, r, standard_library, progress);
}

py::dict resume(const std::filesystem::path& dir, std::optional<int> generations, const std::filesystem::path& script,
                int threads, const std::filesystem::path& cache, const std::filesystem::path& standard_library,
                const py::object& progress) {
  app::ResumeRequest r;
  r.dir = dir;
  r.script = script;
  r.generations = generations;
  r.cache = cache;
  r.execution.threads = threads;
  r.explain = true;
  return outcome_of(&app::resume, r, standard_library, progress);
}

}  // namespace

void bind_run(py::module_& m) {
  m.def("run", &run, py::arg("script"), py::arg("experiment"), py::arg("runs"), py::arg("generations"),
        py::arg("seed"), py::arg("threads"), py::arg("out"), py::arg("set"), py::arg("controllers"), py::arg("cache"),
        py::arg("standard_library"), py::arg("progress"),
        "app::run: an experiment or study of a script file into a directory; a dict (dir, study, ran).");
  m.def("resume", &resume, py::arg("dir"), py::arg("generations"), py::arg("script"), py::arg("threads"),
        py::arg("cache"), py::arg("standard_library"), py::arg("progress"),
        "app::resume: a stopped run or study continued, or carried on to `generations`; a dict (dir, study, ran).");
}

}  // namespace esc::python
