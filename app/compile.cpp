#include "app/compile.hpp"

#include <fmt/format.h>

#include "app/error.hpp"
#include "app/ranks.hpp"
#include "compiler/names.hpp"

namespace esc::app {

namespace {

// "FILE has no WHAT `name`; it declares ...", with the closest name declared.
[[noreturn]] void no_such(const std::filesystem::path& file, std::string_view what, const std::string& name,
                          const std::string& declared, const std::vector<std::string>& names) {
  const auto near = compiler::closest(name, names);
  throw Error(ErrorKind::Script, fmt::format("{} has no {} `{}`; it declares {}", file.string(), what, name, declared),
              near ? fmt::format("did you mean `{}`?", *near) : std::string());
}

template <class T>
std::vector<std::string> names_of(const std::vector<T>& declared) {
  std::vector<std::string> names;
  for (const T& x : declared) names.push_back(x.name);
  return names;
}

}  // namespace

compiler::CompileResult compile(const std::filesystem::path& file, const compiler::CompileOptions& options,
                                Events& events) {
  compiler::CompileResult r = compiler::compile_file(file, options);
  if (!r.ok()) throw Error(ErrorKind::Script, {}, {}, std::make_shared<const compiler::CompileResult>(std::move(r)));
  if (!r.diagnostics.empty() && !follower_rank()) events.warnings(r);
  return r;
}

eval::ExperimentSpec& pick_experiment(compiler::CompileResult& compiled, const std::filesystem::path& file,
                                      const std::string& name) {
  if (compiled.experiments.empty())
    throw Error(ErrorKind::Script, fmt::format("{} declares no experiment to run", file.string()));
  if (name.empty()) return compiled.experiments.front();
  for (auto& e : compiled.experiments)
    if (e.name == name) return e;
  const std::vector<std::string> names = names_of(compiled.experiments);
  no_such(file, "experiment", name, compiler::quoted_list(names, " and "), names);
}

eval::ExperimentSpec& pick_stored_experiment(compiler::CompileResult& compiled, const std::filesystem::path& file,
                                             const std::string& name) {
  for (auto& e : compiled.all_experiments)
    if (e.name == name) return e;
  const std::vector<std::string> names = names_of(compiled.all_experiments);
  no_such(file, "experiment", name, names.empty() ? "none" : compiler::quoted_list(names, " and "), names);
}

std::vector<store::SourceFile> sources_of(const compiler::CompileResult& compiled) {
  std::vector<store::SourceFile> sources;
  for (const auto& [name, text] : compiled.sources) sources.push_back({name, text});
  return sources;
}

Target pick_target(compiler::CompileResult& compiled, const std::filesystem::path& file, const std::string& name) {
  const std::string wanted = name.empty() ? compiled.first_declared : name;
  if (wanted.empty())
    throw Error(ErrorKind::Script, fmt::format("{} declares no experiment or study to run", file.string()));
  for (auto& e : compiled.experiments)
    if (e.name == wanted) return &e;
  for (auto& s : compiled.studies)
    if (s.name == wanted) return &s;
  const std::vector<std::string> experiments = names_of(compiled.experiments), studies = names_of(compiled.studies);
  std::string declared = experiments.empty() ? "" : "experiments " + compiler::quoted_list(experiments, ", ");
  if (!studies.empty())
    declared += (declared.empty() ? "studies " : " and studies ") + compiler::quoted_list(studies, ", ");
  std::vector<std::string> all = experiments;
  all.insert(all.end(), studies.begin(), studies.end());
  no_such(file, "experiment or study", wanted, declared.empty() ? "none" : declared, all);
}

}  // namespace esc::app
