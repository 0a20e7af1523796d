#include "cli/controller_selection.hpp"

#include <algorithm>
#include <optional>

#include "cli/load.hpp"
#include "compiler/names.hpp"

namespace esc::cli {

namespace {

// Index of the compared controller `name`, or nullopt.
std::optional<std::size_t> index_of(const eval::ExperimentSpec& spec, const std::string& name) {
  for (std::size_t i = 0; i < spec.controllers.size(); ++i)
    if (spec.controllers[i].name == name) return i;
  return std::nullopt;
}

// Dependencies whose targets point into the kept controllers, the indices renumbered.
std::vector<eval::Dependency> kept_dependencies(const std::vector<eval::Dependency>& all,
                                                const std::vector<std::size_t>& kept) {
  std::vector<eval::Dependency> out;
  for (const eval::Dependency& d : all) {
    eval::Dependency k{d.experiment, d.controller, {}};
    for (const auto& [controller, behavior] : d.targets) {
      const auto at = std::find(kept.begin(), kept.end(), controller);
      if (at != kept.end()) k.targets.emplace_back(static_cast<std::size_t>(at - kept.begin()), behavior);
    }
    if (!k.targets.empty()) out.push_back(std::move(k));
  }
  return out;
}

}  // namespace

bool select_controllers(const std::vector<std::string>& names, eval::ExperimentSpec& spec, std::string_view where) {
  if (names.empty()) return true;
  std::vector<std::string> compared;
  for (const auto& c : spec.controllers) compared.push_back(c.name);
  std::vector<std::size_t> kept;
  bool ok = true;
  for (const std::string& name : names) {
    const auto i = index_of(spec, name);
    if (!i) {
      complain("esc: error: {}--controllers: experiment `{}` compares no controller `{}`; it compares {}\n", where,
               spec.name, name, compiler::quoted_list(compared, ", "));
      if (const auto near = compiler::closest(name, compared)) complain("help: did you mean `{}`?\n", *near);
      ok = false;
    } else if (std::find(kept.begin(), kept.end(), *i) != kept.end()) {
      complain("esc: error: {}--controllers names `{}` twice\n", where, name);
      ok = false;
    } else {
      kept.push_back(*i);
    }
  }
  if (!ok) return false;
  std::vector<control::ControllerSpec> controllers;
  for (std::size_t i : kept) controllers.push_back(spec.controllers[i]);
  spec.dependencies = kept_dependencies(spec.dependencies, kept);
  spec.controllers = std::move(controllers);
  return true;
}

}  // namespace esc::cli
