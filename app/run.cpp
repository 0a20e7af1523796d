// Starting a run: an experiment or a study of a script, into a new directory.
#include "app/run.hpp"

#include <optional>
#include <variant>

#include <fmt/format.h>

#include "app/compile.hpp"
#include "app/dependencies.hpp"
#include "app/ranks.hpp"
#include "app/run_parts.hpp"
#include "app/store_errors.hpp"

namespace esc::app {

namespace {

Outcome run_study(const RunRequest& r, const compiler::CompileResult& compiled, eval::StudySpec& study,
                  const std::filesystem::path& out, Events& events) {
  apply_to_study(r.overrides, study);
  // Dependencies shared by several conditions are run once: the second finds it in the cache.
  const DependencyContext deps =
      dependency_context(compiled, r.overrides, r.execution, run_cache(r.overrides, out), r.script, events);
  std::vector<store::LaunchInfo> launches;
  std::vector<std::string> names;
  for (eval::ConditionSpec& c : study.conditions) {
    prepare_dependencies(c.experiment, deps);
    launches.push_back(launch_info(r.overrides, r.script, &c.experiment));
    names.push_back(c.name);
  }
  std::int64_t generations = 0;
  for (const eval::ConditionSpec& c : study.conditions) generations += c.experiment.total_generations();
  std::optional<store::StudyDirectory> dir;
  on_rank0([&] {
    dir.emplace(out, study, sources_of(compiled), launches);
    tell(events, Note{Note::Kind::Start,
                      fmt::format("running study {} ({} condition{}: {}) into {}", study.name, names.size(),
                                  names.size() == 1 ? "" : "s", names_of(names), out.string()),
                      out, generations, 0, start_command(launches.front().script, study.name, r.overrides, out)});
  });
  return {out, study.name, run_conditions(study, r.execution, dir, StoredStudy{}, events)};
}

Outcome run_one(const RunRequest& r, const compiler::CompileResult& compiled, eval::ExperimentSpec& spec,
                const std::filesystem::path& out, Events& events) {
  apply_to_experiment(r.overrides, spec);
  prepare_dependencies(spec, dependency_context(compiled, r.overrides, r.execution, run_cache(r.overrides, out),
                                                r.script, events));
  const store::LaunchInfo launch = launch_info(r.overrides, r.script, &spec);
  const auto open = [&] {
    store::RunDirectory dir(out, spec, sources_of(compiled), launch);
    tell(events, Note{Note::Kind::Start,
                      fmt::format("running {} ({} controller{}, {} run{}, {}) into {}", spec.name,
                                  spec.controllers.size(), spec.controllers.size() == 1 ? "" : "s", spec.runs,
                                  spec.runs == 1 ? "" : "s", generations_text(spec), out.string()),
                      out, spec.total_generations(), 0, start_command(launch.script, spec.name, r.overrides, out)});
    return dir;
  };
  eval::CampaignResult result = run_experiment(spec, campaign_options(r.execution, nullptr), open, 0, events);
  return {out, {}, {{spec.name, spec, std::move(result)}}};
}

}  // namespace

Outcome run(const RunRequest& request, const compiler::CompileOptions& options, Events& events) {
  return store_errors_typed([&] {
    compiler::CompileResult compiled = compile(request.script, options, events);
    const Target target = pick_target(compiled, request.script, request.experiment);
    auto* const* study = std::get_if<eval::StudySpec*>(&target);
    const std::string& name = study != nullptr ? (*study)->name : std::get<eval::ExperimentSpec*>(target)->name;
    const std::filesystem::path out = request.out.empty() ? default_out(name) : request.out;
    return disk_full_typed(out, [&] {
      return study != nullptr ? run_study(request, compiled, **study, out, events)
                              : run_one(request, compiled, *std::get<eval::ExperimentSpec*>(target), out, events);
    });
  });
}

}  // namespace esc::app
