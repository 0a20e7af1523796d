// Compiling a script as every esc command does (imports beside the file, then $ESC_PATH, then
// the standard library the package found; a main file not found as given looked up the same
// way), from a file or from text, and the settings a caller gives applied as `esc run --set
// KEY=VALUE` applies them. What is wrong with a script comes back as data (its diagnostics
// and the text the CLI prints), from which the package raises esc.ScriptError; a setting
// refused raises esc.Error.
#include <string>
#include <utility>
#include <vector>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "app/import_path.hpp"
#include "compiler/robot_settings.hpp"
#include "python/src/bindings.hpp"
#include "python/src/compiled_script.hpp"
#include "python/src/errors.hpp"
#include "python/src/observation.hpp"

namespace esc::python {

namespace py = pybind11;

namespace {

const char* severity_name(compiler::Severity s) {
  switch (s) {
    case compiler::Severity::Error: return "error";
    case compiler::Severity::Warning: return "warning";
    case compiler::Severity::Note: return "note";
  }
  return "error";
}

py::dict location(const compiler::SourceRange& where) {
  py::dict d;
  d["file"] = where.file.string();
  d["line"] = where.line;
  d["column"] = where.column;
  d["length"] = where.length;
  return d;
}

py::list diagnostics(const CompiledScript& s) {
  py::list out;
  for (const compiler::Diagnostic& d : s.result.diagnostics) {
    py::dict item = location(d.where);
    item["severity"] = severity_name(d.severity);
    item["message"] = d.message;
    item["help"] = d.help;
    py::list notes;
    for (const auto& [where, text] : d.notes) {
      py::dict note = location(where);
      note["message"] = text;
      notes.append(note);
    }
    item["notes"] = notes;
    out.append(item);
  }
  return out;
}

using Settings = std::vector<std::pair<std::string, std::string>>;

// The settings, (key, value) in order, applied to every experiment of the main file and every
// study condition's, together as `esc run --set` applies them (so `robots=2, roles=2` after
// `roles 3` is one change). An experiment or a study (any of its conditions) that refuses them
// is recorded with the refusal, worded as the CLI words it ("experiment `x`: KEY=VALUE: what is
// wrong"), as `esc run --experiment` would fail for it; when every one refuses them (an
// unknown key), throws Error with the first refusal.
void apply_settings(CompiledScript& s, const Settings& settings) {
  const auto apply = [&settings](eval::ExperimentSpec& e, const std::string& where) -> std::string {
    const compiler::SettingsRefusal refused = compiler::apply_settings_together(e, settings);
    if (!refused.settings.empty()) {
      const auto& [index, why] = refused.settings.front();
      return where + ": " + settings[index].first + "=" + settings[index].second + ": " + why;
    }
    if (refused.together.empty()) return {};
    std::string named;
    for (const auto& [key, value] : settings) named += (named.empty() ? "" : " ") + key + "=" + value;
    return where + ": " + named + ": " + refused.together;
  };
  std::string first;
  const auto record = [&](const std::string& name, std::string error) {
    if (error.empty()) return;
    if (first.empty()) first = error;
    s.refused.try_emplace(name, std::move(error));
  };
  for (eval::ExperimentSpec& e : s.result.experiments) record(e.name, apply(e, "experiment `" + e.name + "`"));
  // A study takes the settings when every condition does.
  for (eval::StudySpec& study : s.result.studies)
    for (eval::ConditionSpec& c : study.conditions)
      record(study.name, apply(c.experiment, "study `" + study.name + "`, condition `" + c.name + "`"));
  if (!first.empty() && s.refused.size() == s.result.experiments.size() + s.result.studies.size()) throw Error(first);
}

py::dict controller_info(const control::ControllerSpec& c, const eval::ExperimentSpec& x) {
  py::dict d;
  d["name"] = c.name;
  d["architecture"] = c.architecture();
  d["head"] = c.head_name();
  d["genome_size"] = x.genome_length(c);
  d["roles"] = x.roles;
  std::vector<std::string> inputs;
  if (!c.is_tree() && !c.per_body())
    for (const expr::Slot slot : c.mlp.inputs) inputs.push_back(slot_name(slot, x.robot));
  d["inputs"] = inputs;
  // A controller per body: each body's network's inputs, named as that body reads them.
  py::list per_body;
  for (std::size_t b = 0; b < c.body_networks.size() && b < std::max<std::size_t>(x.bodies.size(), 1); ++b) {
    const control::ControllerSpec& n = c.networks.at(c.body_networks[b]);
    const sim::RobotParams& body = x.bodies.empty() ? x.robot : x.bodies[b].params;
    std::vector<std::string> read;
    for (const expr::Slot slot : n.mlp.inputs) read.push_back(slot_name(slot, body));
    per_body.append(py::make_tuple(x.bodies.empty() ? x.resolved_settings.at("robot") : x.bodies[b].name, read));
  }
  d["per_body"] = per_body;
  d["choices"] = c.choice_names();
  d["graph"] = c.is_graph();
  return d;
}

py::list controllers(const CompiledScript& s, const std::string& experiment) {
  py::list out;
  const eval::ExperimentSpec& x = find_experiment(s, experiment);
  for (const control::ControllerSpec& c : x.controllers) out.append(controller_info(c, x));
  return out;
}

// Each body of `experiment`'s robots, in robot order: dicts of name (its robot declaration),
// robots (how many have it), drive, radius_m, outline_m (its corners from the axle; empty: the
// disc) and sensors (what it offers a controller, by the names its scripts read them).
py::list bodies(const CompiledScript& s, const std::string& experiment) {
  const eval::ExperimentSpec& x = find_experiment(s, experiment);
  std::vector<eval::ExperimentSpec::GroupBody> listed = x.bodies;
  if (listed.empty()) listed.push_back({x.resolved_settings.at("robot"), x.robot, x.robots});
  py::list out;
  for (const eval::ExperimentSpec::GroupBody& b : listed) {
    py::dict d;
    d["name"] = b.name;
    d["robots"] = b.count;
    d["drive"] = compiler::robot_value_text(*compiler::find_robot_setting("drive"), b.params);
    d["radius_m"] = b.params.body_radius_m;
    std::vector<std::pair<double, double>> outline;
    for (const sim::Vec2& v : b.params.outline) outline.emplace_back(v.x, v.y);
    d["outline_m"] = outline;
    std::vector<std::string> sensors;
    for (const expr::Slot slot : senses(b.params)) sensors.push_back(slot_name(slot, b.params));
    d["sensors"] = sensors;
    out.append(std::move(d));
  }
  return out;
}

// A script that compiled gets its settings; one with errors is returned as it is, for its
// diagnostics.
std::shared_ptr<CompiledScript> compiled(compiler::CompileResult result, std::filesystem::path file,
                                         const Settings& settings) {
  auto s = std::make_shared<CompiledScript>(CompiledScript{std::move(result), std::move(file), {}});
  if (s->result.ok()) apply_settings(*s, settings);
  return s;
}

}  // namespace

void bind_script(py::module_& m) {
  py::class_<CompiledScript, std::shared_ptr<CompiledScript>>(m, "CompiledScript",
                                                              "A compiled script (see esc.Script, which wraps it).")
      .def_property_readonly("ok", [](const CompiledScript& s) { return s.result.ok(); },
                             "Whether it compiled without errors.")
      .def_property_readonly("file", [](const CompiledScript& s) { return s.file.string(); },
                             "The script's file, or the pseudo file name of a script given as text.")
      .def_property_readonly("diagnostics", &diagnostics,
                             "Every error, warning and note: dicts of severity, file, line, column, length, "
                             "message, help and notes.")
      .def_property_readonly(
          "rendered", [](const CompiledScript& s) { return compiler::render_all(s.result.diagnostics, s.result.sources); },
          "The diagnostics as `esc check` prints them.")
      .def_property_readonly(
          "experiments",
          [](const CompiledScript& s) {
            std::vector<std::string> names;
            for (const eval::ExperimentSpec& e : s.result.experiments) names.push_back(e.name);
            return names;
          },
          "The main file's experiments, in declaration order.")
      .def_property_readonly(
          "refused", [](const CompiledScript& s) { return s.refused; },
          "The experiments and studies that refused the settings given, each with why, as `esc run --set` says it.")
      .def_property_readonly(
          "studies",
          [](const CompiledScript& s) {
            std::vector<std::pair<std::string, std::vector<std::string>>> studies;
            for (const eval::StudySpec& st : s.result.studies) {
              std::vector<std::string> conditions;
              for (const eval::ConditionSpec& c : st.conditions) conditions.push_back(c.name);
              studies.emplace_back(st.name, std::move(conditions));
            }
            return studies;
          },
          "The main file's studies, in declaration order, each with its conditions.")
      .def("controllers", &controllers, py::arg("experiment"),
           "The controllers `experiment` compares, in order: dicts of name, architecture, head, genome_size "
           "(0 for a tree; a network's weights times roles), roles (the genomes evolved together, one per role), "
           "inputs (the network's, by observable name) and choices (actions or behaviors).")
      .def(
          "controller",
          [](const CompiledScript& s, const std::string& experiment, const std::string& name) {
            const eval::ExperimentSpec& x = find_experiment(s, experiment);
            return controller_info(find_controller(x, name), x);
          },
          py::arg("experiment"), py::arg("name"),
          "Controller `name` of `experiment`, as controllers() describes it; ValueError naming those it compares.")
      .def("bodies", &bodies, py::arg("experiment"),
           "The bodies of `experiment`'s robots, in robot order: dicts of name, robots (how many have it), drive, "
           "radius_m, outline_m and sensors (by the names its scripts read them).")
      .def(
          "settings", [](const CompiledScript& s, const std::string& e) { return find_experiment(s, e).resolved_settings; },
          py::arg("experiment"), "Every setting of `experiment` as resolved (what settings.json holds).");

  m.def(
      "compile_file",
      [](const std::filesystem::path& file, const std::filesystem::path& standard_library, const Settings& settings) {
        return compiled(compiler::compile_file(file, app::compile_options(standard_library)), file, settings);
      },
      py::arg("file"), py::arg("standard_library"), py::arg("settings"),
      "Compiles the script `file` (imports searched beside it, in $ESC_PATH, then in `standard_library`) and "
      "applies `settings`, (key, value) pairs, to every experiment and study condition as `esc run --set` does. "
      "Raises esc.Error for a setting refused.");
  m.def("find_main_script", &app::find_main_script, py::arg("file"), py::arg("standard_library"),
        "`file` as given when it exists or is absolute; else the first directory of $ESC_PATH, then "
        "`standard_library`, that holds it (as an import is found); else `file`.");
  m.def(
      "compile_source",
      [](const std::string& text, const std::filesystem::path& name, const std::filesystem::path& standard_library,
         const Settings& settings) {
        return compiled(compiler::compile_source(text, name, app::compile_options(standard_library)), name, settings);
      },
      py::arg("text"), py::arg("name"), py::arg("standard_library"), py::arg("settings"),
      "Compiles script text as compile_file does; `name` is its file name in diagnostics, and relative imports "
      "are searched in its directory first.");
}

}  // namespace esc::python
