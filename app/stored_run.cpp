#include "app/stored_run.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "app/compile.hpp"
#include "app/dependencies.hpp"
#include "app/error.hpp"
#include "app/settings.hpp"
#include "app/stored_sources.hpp"
#include "app/version.hpp"
#include "runtime/eval/run_optimizer.hpp"
#include "runtime/eval/settings_history.hpp"
#include "runtime/store/run_directory.hpp"
#include "runtime/store/seed_json.hpp"

namespace esc::app {

namespace {

// The experiment a stored condition ran: its study's condition, as the study's script gives it.
eval::ExperimentSpec& condition_of(compiler::CompileResult& compiled, const store::StoredCondition& stored) {
  for (eval::StudySpec& study : compiled.studies)
    if (study.name == stored.study)
      for (eval::ConditionSpec& c : study.conditions)
        if (c.name == stored.name) return c.experiment;
  throw Error(ErrorKind::Script, fmt::format("the stored sources no longer declare condition `{}` of study `{}`",
                                             stored.name, stored.study));
}

// Evaluation only: where evolution started does not change it, and the behaviors it froze
// come from the cache as they were.
eval::ExperimentSpec for_evaluation(eval::ExperimentSpec spec, const compiler::CompileResult& compiled,
                                    const Overrides& settings, const StoredRun& run, Events& events) {
  spec.start_from.reset();
  const std::filesystem::path cache = !settings.cache.empty() ? settings.cache : cache_of_run(run.root);
  DependencyContext reuse{
      compiled, [given = for_dependencies(settings)](eval::ExperimentSpec& d) { apply_settings(given, d); }, {}, {}, cache,
      version(), events};
  reuse.reuse_only = true;
  prepare_dependencies(spec, reuse);
  return spec;
}

}  // namespace

eval::ExperimentSpec experiment_of_run(const StoredRun& run, const compiler::CompileOptions& options, Events& events) {
  const store::StoredExperiment& stored = *run.stored;
  const Overrides settings = stored_overrides(stored, run.root);
  const StoredSources sources(stored);
  compiler::CompileResult compiled = sources.compile(options, events);
  if (store::campaign_hash(stored.name, sources_of(compiled)) != stored.content_hash)
    throw Error(ErrorKind::Results,
                fmt::format("the sources stored in {} do not compile back to the run's script", run.root.string()));
  eval::ExperimentSpec& spec = stored.condition ? condition_of(compiled, *stored.condition)
                                                : pick_stored_experiment(compiled, stored.script, stored.name);
  apply_settings(settings, spec);
  // A run carried on by a resume stored the generations it was carried on to.
  const std::optional<int> carried = stored_carry_on(stored, run.root);
  if (!set_generations(spec, carried))
    throw Error(ErrorKind::Results,
                fmt::format("{} is damaged: it was carried on to {} generations", run.root.string(), *carried));
  if (!eval::same_settings(spec.resolved_settings, stored.settings))
    throw Error(ErrorKind::Results, fmt::format("the stored sources of {} no longer compile to the settings the run used",
                                                run.dir.string()));
  return for_evaluation(spec, compiled, settings, run, events);
}

eval::ExperimentSpec experiment_for_run(const StoredRun& run, const std::filesystem::path& script,
                                        const std::string& experiment, const compiler::CompileOptions& options,
                                        Events& events) {
  Overrides settings = run.stored != nullptr ? stored_overrides(*run.stored, run.root) : Overrides{};
  settings.runs.reset();
  settings.generations.reset();
  settings.seed.reset();
  settings.set.clear();
  compiler::CompileResult compiled = compile(script, options, events);
  eval::ExperimentSpec& spec = pick_experiment(compiled, script, experiment);
  apply_settings(settings, spec);
  return for_evaluation(spec, compiled, settings, run, events);
}

FinishedRun finished_run(const StoredRun& stored, const std::string& controller, int run) {
  const auto c = std::find_if(stored.stored->controllers.begin(), stored.stored->controllers.end(),
                              [&](const store::StoredController& x) { return x.name == controller; });
  if (c == stored.stored->controllers.end())
    throw Error(ErrorKind::Results, fmt::format("the run has no controller `{}`", controller));
  const auto finished = std::find_if(c->finished.begin(), c->finished.end(),
                                     [&](const eval::RunResult& r) { return r.run == run; });
  if (finished == c->finished.end())
    throw Error(ErrorKind::Results, fmt::format("run {} of {} is not finished", run + 1, controller));
  return {&*c, &*finished};
}

evo::Members final_members(const StoredRun& stored, const eval::ExperimentSpec& spec, const std::string& controller,
                           int run) {
  const auto compared = std::find_if(spec.controllers.begin(), spec.controllers.end(),
                                     [&](const control::ControllerSpec& x) { return x.name == controller; });
  if (compared == spec.controllers.end())
    throw Error(ErrorKind::Results, fmt::format("the run has no controller `{}`", controller));
  const auto [c, finished] = finished_run(stored, controller, run);
  evo::Problem problem = spec.problem_of(*compared);
  problem.seed = finished->seed;
  try {
    eval::RunOptimizer made = eval::make_run_optimizer(spec, *compared, problem);
    eval::load_run_state(made, *compared, store::ResultsDb::open(stored.root, true).load_state(*c, run));
    if (auto kept = made.optimizer->members(false)) return std::move(*kept);
  } catch (const std::invalid_argument& e) {
    throw Error(ErrorKind::Results, e.what());
  }
  throw Error(ErrorKind::Results,
              fmt::format("{} ({}) keeps no front or archive beside each run's best: replay its best instead", controller,
                          c->algorithm));
}

bool genome_file_intact(const nlohmann::json& j) {
  if (!j.contains("checksum")) return true;
  const std::string tree = j.contains("tree") ? j["tree"].get<std::string>() : "";
  return j["checksum"].get<std::string>() ==
         store::genome_checksum(j.at("controller").get<std::string>(), j.at("run").get<int>(),
                                j.at("genome").get<std::vector<double>>(), j.at("fitness").get<double>(),
                                store::seed_from_json(j.at("evaluation_seed")), tree);
}

std::optional<std::uint64_t> genome_file_seed(const nlohmann::json& j) {
  if (!j.contains("evaluation_seed")) return std::nullopt;
  return store::seed_from_json(j["evaluation_seed"]);
}

}  // namespace esc::app
