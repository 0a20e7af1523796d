// `esc run` of a study: every condition, one after another (each a campaign whose runs
// advance together), into one directory; and its continuation after a stop.
#include <algorithm>
#include <optional>

#include <fmt/format.h>

#include "cli/controller_selection.hpp"
#include "cli/end_table.hpp"
#include "cli/load.hpp"
#include "cli/run_support.hpp"
#include "runtime/store/study_directory.hpp"
#include "runtime/store/untouched_load.hpp"

namespace esc::cli {

namespace {

std::string trimmed(std::string_view t) {
  while (!t.empty() && (t.front() == ' ' || t.front() == '\t')) t.remove_prefix(1);
  while (!t.empty() && (t.back() == ' ' || t.back() == '\t')) t.remove_suffix(1);
  return std::string(t);
}

// Refuses a command-line setting of a key the study varies: one value for every condition
// would flatten the study. Prints each; false if any.
bool vary_nothing_given(const RunOptions& o, const eval::StudySpec& study) {
  const auto settings = override_settings(o);
  if (!settings) return false;
  const std::vector<std::string> varied = study.varied_keys();
  // What a condition gives an experiment it depends on (`energy.generations 60`): the
  // command line's `generations` would override that too.
  const auto given = [&](const std::string& k) -> const eval::DependencySetting* {
    for (const eval::ConditionSpec& c : study.conditions)
      for (const eval::DependencySetting& d : c.experiment.dependency_settings)
        if (d.key == k) return &d;
    return nullptr;
  };
  bool ok = true;
  for (const auto& [key, value] : *settings) {
    const std::string k = trimmed(key);
    if (const eval::DependencySetting* d = given(k)) {
      complain("esc: error: {}={}: study `{}` gives `{}` to experiment `{}` in its conditions ({}.{} {}); the "
               "command line's value would replace it (to shorten such a study, run its experiments with "
               "--experiment)\n",
               k, trimmed(value), study.name, k, d->path.back(), fmt::join(d->path, "."), d->key, d->value);
      ok = false;
      continue;
    }
    if (std::find(varied.begin(), varied.end(), k) == varied.end()) continue;
    complain("esc: error: {}={}: study `{}` varies `{}` across its conditions; one value for all of them would "
             "flatten it (to run one condition with another value, run its experiment with --experiment and "
             "--set)\n",
             k, trimmed(value), study.name, k);
    ok = false;
  }
  return ok;
}

// The command line's overrides on every condition; false after printing an error.
bool apply_to_conditions(const RunOptions& o, eval::StudySpec& study) {
  for (eval::ConditionSpec& c : study.conditions) {
    const std::string where = fmt::format("condition `{}`: ", c.name);
    if (!apply_overrides(o, c.experiment, where) || !select_controllers(o.controllers, c.experiment, where) ||
        !fits_in_memory(c.experiment))
      return false;
  }
  if (o.seed) study.seed = *o.seed;
  return true;
}

// What a stopped study left: its database and one stored experiment per condition; none
// for a new study.
struct Stored {
  // Per condition, where it resumes from (read from a copy of the database).
  const std::vector<eval::ResumePoint>* points = nullptr;
  const std::vector<store::StoredExperiment>* conditions = nullptr;
  // Per condition, the generations `--resume DIR --generations G` carries it on to, if any.
  const std::vector<std::optional<int>>* carry_on = nullptr;
};

// Runs every condition not finished yet and prints the study's table.
int run_conditions(const eval::StudySpec& study, const RunOptions& o, std::optional<store::StudyDirectory>& dir,
                   const Stored& stored, const std::filesystem::path& out) {
  std::vector<ConditionResult> results;
  for (std::size_t i = 0; i < study.conditions.size(); ++i) {
    const eval::ConditionSpec& c = study.conditions[i];
    const store::StoredExperiment* before = stored.conditions != nullptr ? &(*stored.conditions)[i] : nullptr;
    // The generations it is carried on to; 0 when it is not (a run has at least one).
    const int carry_on = stored.carry_on != nullptr ? (*stored.carry_on)[i].value_or(0) : 0;
    if (before != nullptr && before->finished() && carry_on == 0) {
      results.push_back({c.name, &c.experiment, before->result()});
      continue;
    }
    const eval::ResumePoint point =
        before != nullptr ? (*stored.points)[i] : eval::ResumePoint{};
    say("esc: condition {}/{} {}: {} ({} controller{}, {} run{}, {})\n", i + 1, study.conditions.size(), c.name,
        c.experiment.name, c.experiment.controllers.size(), c.experiment.controllers.size() == 1 ? "" : "s",
        c.experiment.runs, c.experiment.runs == 1 ? "" : "s", generations_text(c.experiment));
    std::optional<store::RunDirectory> run;
    if (dir) {
      std::optional<store::StudyDirectory::CarryOn> recorded;
      if (carry_on > 0) {
        recorded = store::StudyDirectory::CarryOn{&c.experiment, before->overrides};
        recorded->overrides["carry_on"] = carry_on;
      }
      run.emplace(dir->open_condition(i, point, recorded));
    }
    results.push_back({c.name, &c.experiment,
                       campaign_on_all_ranks(c.experiment, campaign_options(o, before != nullptr ? &point : nullptr),
                                             run ? &*run : nullptr, generations_done(point))});
  }
  if (follower_rank()) return kExitOk;
  print_study_table(study.name, results);
  fmt::print("\nresults: {}/summary.json (report: esc report {})\n", out.string(), out.string());
  return kExitOk;
}

std::string names_of(const std::vector<std::string>& names) {
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

}  // namespace

int run_study(const RunOptions& o, compiler::CompileResult& compiled, eval::StudySpec& study) {
  if (!vary_nothing_given(o, study) || !apply_to_conditions(o, study)) return kExitBadInput;
  const std::filesystem::path out = o.out.empty() ? default_out(study.name) : o.out;
  // Dependencies shared by several conditions are run once: the second finds it in the cache.
  const DependencyContext deps = dependency_context(compiled, o, run_cache(o, out), o.file);
  std::vector<store::LaunchInfo> launches;
  std::vector<std::string> names;
  for (eval::ConditionSpec& c : study.conditions) {
    if (!prepare_dependencies(c.experiment, deps)) return kExitBadInput;
    launches.push_back(launch_info(o, o.file, &c.experiment));
    names.push_back(c.name);
  }
  std::optional<store::StudyDirectory> dir;
  const auto open = [&] {
    dir.emplace(out, study, sources_of(compiled), launches);
    fmt::print("esc: running study {} ({} condition{}: {}) into {}\n", study.name, names.size(),
               names.size() == 1 ? "" : "s", names_of(names), out.string());
  };
  if (!open_on_rank0(open)) return kExitBadInput;
  return run_conditions(study, o, dir, Stored{}, out);
}

int resume_study(const RunOptions& o, std::vector<store::StoredExperiment> all) {
  const std::vector<store::StoredExperiment> stored = store::study_conditions(std::move(all));
  const store::StoredExperiment& first = stored.front();
  const std::string& name = first.condition->study;
  const auto finished = std::count_if(stored.begin(), stored.end(), [](const auto& e) { return e.finished(); });
  const auto complete = [&] {
    say("esc: {} is complete (study {}, {} conditions); nothing to resume\n", o.resume.string(), name, stored.size());
    return kExitOk;
  };
  if (static_cast<std::size_t>(finished) == stored.size() && !o.generations) return complete();
  const auto script = resume_script(o, first.script);
  if (!script) return kExitBadInput;
  compiler::CompileResult compiled = compile_to_resume(o, *script);
  if (!compiled.ok()) return kExitBadInput;
  const auto it = std::find_if(compiled.studies.begin(), compiled.studies.end(),
                               [&](const eval::StudySpec& s) { return s.name == name; });
  if (it == compiled.studies.end()) {
    complain("esc: error: {} has no study `{}` (the run in {} is one); cannot resume\n", script->string(), name,
             o.resume.string());
    return kExitBadInput;
  }
  eval::StudySpec& study = *it;
  std::vector<std::string> now, then;
  for (const eval::ConditionSpec& c : study.conditions) now.push_back(c.name);
  for (const store::StoredExperiment& e : stored) then.push_back(e.condition->name);
  if (now != then) {
    complain("esc: error: study `{}` in {} has the conditions {}, but the run in {} has {}; cannot resume\n", name,
             script->string(), names_of(now), o.resume.string(), names_of(then));
    return kExitBadInput;
  }
  RunOptions replay = stored_overrides(first, o.resume);
  if (!apply_to_conditions(replay, study)) return kExitBadInput;
  replay.threads = o.threads;
  replay.runs_at_once = o.runs_at_once;
  // Each condition as stored (carried on by a previous --generations, if it was), and the
  // generations a new --generations carries it on to.
  const std::vector<store::SourceFile> sources = sources_of(compiled);
  std::vector<std::optional<int>> carried(stored.size()), extend(stored.size());
  bool any = false;
  for (std::size_t i = 0; i < stored.size(); ++i) {
    carried[i] = stored_carry_on(stored[i], o.resume);
    eval::ExperimentSpec as_stored = study.conditions[i].experiment;
    if (!set_generations(as_stored, carried[i])) {
      complain("esc: error: {} is damaged: condition {} was carried on to {} generations\n", o.resume.string(),
               stored[i].condition->name, *carried[i]);
      return kExitBadInput;
    }
    if (!resumable(as_stored, sources, stored[i], *script, o)) return kExitBadInput;
    extend[i] = carry_on_to(o, as_stored);
    if (extend[i] && *extend[i] < 0) return kExitBadInput;
    any = any || extend[i] || !stored[i].finished();
  }
  if (!any) return complete();
  // Dependencies last: a script that cannot resume should not first run them. They, and what
  // each condition received from them, are checked with the generations it was launched with.
  const std::filesystem::path cache = resume_cache(o, replay);
  const DependencyContext deps = dependency_context(compiled, replay, cache, *script);
  for (std::size_t i = 0; i < stored.size(); ++i) {
    eval::ExperimentSpec& x = study.conditions[i].experiment;
    if (!stored[i].finished() || extend[i])
      if (!prepare_dependencies(x, deps) || !same_inputs(x, stored[i], cache, o.resume)) return kExitBadInput;
    (void)set_generations(x, extend[i] ? extend[i] : carried[i]);
  }
  if (o.generations)
    say("esc: carrying study {} in {} on to {} generations: {} of {} conditions finished\n", name, o.resume.string(),
        *o.generations, finished, stored.size());
  else
    say("esc: resuming study {} in {}: {} of {} conditions finished\n", name, o.resume.string(), finished,
        stored.size());
  // Where each condition to run resumes from, read from a copy: a refused carry-on leaves the
  // directory as it was.
  std::vector<const store::StoredExperiment*> before;
  std::vector<const eval::ExperimentSpec*> specs;
  for (std::size_t i = 0; i < stored.size(); ++i) {
    before.push_back(stored[i].finished() && !extend[i] ? nullptr : &stored[i]);
    specs.push_back(&study.conditions[i].experiment);
  }
  const std::vector<eval::ResumePoint> points = store::resume_points_untouched(o.resume, before, specs);
  std::optional<store::StudyDirectory> dir;
  if (!open_on_rank0([&] { dir.emplace(o.resume, stored); })) return kExitBadInput;
  return run_conditions(study, replay, dir, Stored{&points, &stored, &extend}, o.resume);
}

}  // namespace esc::cli
