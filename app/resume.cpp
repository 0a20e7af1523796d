// Continuing a run or a study that stopped, or carrying it on to more generations. A run
// directory holds one stored experiment, a study's one per condition: both resume the same
// way, condition by condition.
#include <algorithm>
#include <memory>
#include <optional>

#include <fmt/format.h>

#include "app/compile.hpp"
#include "app/dependencies.hpp"
#include "app/error.hpp"
#include "app/ranks.hpp"
#include "app/resume_checks.hpp"
#include "app/run.hpp"
#include "app/run_parts.hpp"
#include "app/store_errors.hpp"
#include "runtime/store/directory_lock.hpp"
#include "runtime/store/untouched_load.hpp"

namespace esc::app {

namespace {

// What the directory holds: one experiment, or a study's conditions.
struct Stored {
  std::vector<store::StoredExperiment> experiments;
  bool study = false;
  std::optional<store::LogScan> log_damage;   // what SQLite dropped from a damaged log
  [[nodiscard]] const store::StoredExperiment& first() const { return experiments.front(); }
  [[nodiscard]] std::size_t finished() const {
    return static_cast<std::size_t>(std::count_if(experiments.begin(), experiments.end(),
                                                  [](const auto& e) { return e.finished(); }));
  }
};

// `esc run` as the stopped run was started, into `dir` again.
std::string restart_command(const store::NothingStored::Launch& launch, const std::filesystem::path& dir) {
  Overrides o;
  try {
    o = overrides_from_json(launch.overrides, dir);
  } catch (const store::StoreError&) {   // unreadable: the script and target still help
  }
  return start_command(launch.script, launch.target, o, dir);
}

// Read from a copy: a refused resume leaves every byte of the directory as it was.
Stored load(const std::filesystem::path& dir) {
  std::vector<store::StoredExperiment> all;
  std::optional<store::LogScan> log_damage;
  try {
    store::UntouchedRead read = store::read_untouched(dir);
    all = std::move(read.experiments);
    log_damage = read.log_damage;
  } catch (const store::NothingStored& e) {
    if (!e.launch())
      throw Error(ErrorKind::Results,
                  fmt::format("{}; nothing was stored to resume: start it again with `esc run FILE --out {}` (finished "
                              "dependencies in its deps/ are reused)",
                              e.what(), dir.string()));
    // The command as a hint of its own, whole: a long `quoted` text is shortened in a message.
    throw Error(ErrorKind::Results,
                fmt::format("{}; nothing was stored to resume: start it again as it was started (finished "
                            "dependencies in its deps/ are reused)",
                            e.what()),
                restart_command(*e.launch(), dir));
  }
  if (!all.empty() && all.front().condition) return {store::study_conditions(std::move(all)), true, log_damage};
  if (all.size() != 1)
    throw Error(ErrorKind::Results,
                fmt::format("{} holds {} experiments; a run directory holds one", dir.string(), all.size()));
  return {std::move(all), false, log_damage};
}

// The generations `e` has stored, all its runs together.
std::int64_t stored_generations(const store::StoredExperiment& e) {
  std::int64_t n = 0;
  for (const store::StoredController& c : e.controllers) {
    for (const eval::RunResult& f : c.finished) n += static_cast<std::int64_t>(f.generations.size());
    for (const eval::RunState& s : c.in_progress) n += static_cast<std::int64_t>(s.generations.size());
  }
  return n;
}

// The command-line settings `e` was launched with, and the generations it is carried on to:
// what a carry-on records, for a later plain resume.
nlohmann::ordered_json carry_on_overrides(const store::StoredExperiment& e, int generations) {
  nlohmann::ordered_json overrides = e.overrides;
  overrides["carry_on"] = generations;
  return overrides;
}

std::string complete_text(const std::filesystem::path& dir, const Stored& s) {
  const store::StoredExperiment& e = s.first();
  if (s.study)
    return fmt::format("{} is complete (study {}, {} conditions); nothing to resume", dir.string(),
                       e.condition->study, s.experiments.size());
  return fmt::format("{} is complete ({} x {} runs x {} generations); nothing to resume", dir.string(),
                     e.controllers.size(), e.runs, e.generations);
}

// The study the directory holds, as the script declares it now, with the same conditions.
eval::StudySpec& stored_study(compiler::CompileResult& compiled, const Stored& s, const std::filesystem::path& script,
                              const std::filesystem::path& dir) {
  const std::string& name = s.first().condition->study;
  const auto it = std::find_if(compiled.studies.begin(), compiled.studies.end(),
                               [&](const eval::StudySpec& x) { return x.name == name; });
  if (it == compiled.studies.end())
    throw Error(ErrorKind::Script, fmt::format("{} has no study `{}` (the run in {} is one); cannot resume",
                                               script.string(), name, dir.string()));
  std::vector<std::string> now, then;
  for (const eval::ConditionSpec& c : it->conditions) now.push_back(c.name);
  for (const store::StoredExperiment& e : s.experiments) then.push_back(e.condition->name);
  if (now != then)
    throw Error(ErrorKind::Script,
                fmt::format("study `{}` in {} has the conditions {}, but the run in {} has {}; cannot resume", name,
                            script.string(), names_of(now), dir.string(), names_of(then)));
  return *it;
}

Outcome resume_typed(const ResumeRequest& r, const compiler::CompileOptions& options, Events& events) {
  // Held from the start (rank 0 writes): a run still writing into the directory refuses
  // this one before anything is read or told.
  std::shared_ptr<const store::DirectoryLock> lock;
  std::error_code ec;
  const bool writes = !follower_rank() && std::filesystem::is_directory(r.dir, ec);
  if (writes) {
    try {
      lock = store::DirectoryLock::acquire(r.dir);
    } catch (const store::StoreError& e) {
      throw Error(ErrorKind::Results, e.what());
    }
  }
  const Stored stored = load(r.dir);
  const std::size_t n = stored.experiments.size();
  const auto complete = [&] {
    tell(events, Note::Kind::Complete, complete_text(r.dir, stored));
    return Outcome{r.dir, stored.study ? stored.first().condition->study : std::string(), {}, false};
  };
  if (stored.finished() == n && !r.generations) return complete();   // a read-only one too: nothing to write
  if (writes)
    require_writable(r.dir, "a resume writes the generations it runs into the run's directory",
                     fmt::format("copy it where you may write and resume the copy: cp -r {} COPY && esc run --resume "
                                 "COPY", r.dir.string()));
  if (stored.log_damage)
    tell(events, Note::Kind::Warning,
         fmt::format("{}: the generations they held are run again",
                     store::log_damage_text(r.dir / store::kDatabaseFile, *stored.log_damage)));
  const std::filesystem::path script = resume_script(r, stored.first().script);
  compiler::CompileResult compiled = compile_to_resume(r, script, options, events);

  // Each stored experiment's spec: the study's conditions, or the one experiment.
  eval::StudySpec* study = stored.study ? &stored_study(compiled, stored, script, r.dir) : nullptr;
  std::vector<eval::ExperimentSpec*> specs;
  if (study != nullptr)
    for (eval::ConditionSpec& c : study->conditions) specs.push_back(&c.experiment);
  else
    specs.push_back(&pick_stored_experiment(compiled, script, stored.first().name));
  // The overrides it was launched with, for it and its dependencies.
  const Overrides replay = stored_overrides(stored.first(), r.dir);
  if (study != nullptr)
    apply_to_conditions(replay, *study);
  else
    apply_to_experiment(replay, *specs.front());

  // Each as stored (carried on by a previous carry-on, if it was), and the generations the
  // request carries it on to.
  const std::vector<store::SourceFile> sources = sources_of(compiled);
  std::vector<std::optional<int>> carried(n), extend(n);
  bool any = false;
  for (std::size_t i = 0; i < n; ++i) {
    const store::StoredExperiment& e = stored.experiments[i];
    carried[i] = stored_carry_on(e, r.dir);
    eval::ExperimentSpec as_stored = *specs[i];
    if (!set_generations(as_stored, carried[i]))
      throw Error(ErrorKind::Results, fmt::format("{} is damaged: {} carried on to {} generations", r.dir.string(),
                                                  study != nullptr ? "condition " + e.condition->name + " was"
                                                                   : std::string("it was"),
                                                  *carried[i]));
    check_resumable(as_stored, sources, e, script, r);
    extend[i] = carry_on_to(r, as_stored);
    any = any || extend[i] || !e.finished();
  }
  if (!any) return complete();
  if (is_cache_entry(r.dir))
    // Its dependents would read the longer run under the fingerprint of the shorter.
    throw Error(ErrorKind::Results,
                fmt::format("{} is an entry of a dependency cache, which its dependents read as it was made; to carry "
                            "it on, copy it elsewhere without its {} and give --cache {}",
                            r.dir.string(), kFingerprintFile, r.dir.parent_path().string()));

  // Dependencies last: a script that cannot resume should not first run them. They, and what
  // each received from them, are checked with the generations it was launched with: a
  // carry-on extends the experiment alone.
  const std::filesystem::path cache = resume_cache(r, replay);
  const DependencyContext deps = dependency_context(compiled, replay, r.execution, cache, script, events);
  std::vector<const store::StoredExperiment*> before;
  for (std::size_t i = 0; i < n; ++i) {
    const bool runs = !stored.experiments[i].finished() || extend[i];
    if (runs) {
      prepare_dependencies(*specs[i], deps);
      check_same_inputs(*specs[i], stored.experiments[i], cache, r.dir);
    }
    (void)set_generations(*specs[i], extend[i] ? extend[i] : carried[i]);
    before.push_back(runs ? &stored.experiments[i] : nullptr);
  }
  // Where each resumes from, read from a copy too: a carry-on refused here leaves the
  // directory as it was.
  const std::vector<const eval::ExperimentSpec*> as_run(specs.begin(), specs.end());
  const std::vector<eval::ResumePoint> points = store::resume_points_untouched(r.dir, before, as_run);

  if (study != nullptr) {
    const std::size_t finished = stored.finished();
    // The study's generations, every condition's runs together: what a stop counts.
    std::int64_t generations = 0, done = 0;
    for (std::size_t i = 0; i < n; ++i) {
      generations += specs[i]->total_generations();
      done += stored_generations(stored.experiments[i]);
    }
    tell(events, Note{Note::Kind::Resume,
                      r.generations
                          ? fmt::format("carrying study {} in {} on to {} generations: {} of {} conditions finished",
                                        study->name, r.dir.string(), *r.generations, finished, n)
                          : fmt::format("resuming study {} in {}: {} of {} conditions finished", study->name,
                                        r.dir.string(), finished, n),
                      r.dir, generations, done});
    std::optional<store::StudyDirectory> dir;
    on_rank0([&] {
      dir.emplace(r.dir, stored.experiments);
      // Every condition's target recorded before the first runs on: a plain resume of a
      // carry-on stopped in any condition takes each to it.
      using CarryOn = store::StudyDirectory::CarryOn;
      std::vector<std::optional<CarryOn>> carried_on(n);
      for (std::size_t i = 0; i < n; ++i)
        if (extend[i]) carried_on[i] = CarryOn{specs[i], carry_on_overrides(stored.experiments[i], *extend[i])};
      dir->carry_on(carried_on);
    });
    return {r.dir, study->name,
            run_conditions(*study, r.execution, dir, StoredStudy{&points, &stored.experiments, &extend}, events)};
  }
  eval::ExperimentSpec& spec = *specs.front();
  const eval::ResumePoint& point = points.front();
  const std::int64_t done = generations_done(point);
  tell(events, Note{Note::Kind::Resume,
                    extend.front()
                        ? fmt::format("carrying {} in {} on to {} generations: {} of {} generations done", spec.name,
                                      r.dir.string(), *extend.front(), done, spec.total_generations())
                        : fmt::format("resuming {} in {}: {} of {} generations done", spec.name, r.dir.string(), done,
                                      spec.total_generations()),
                    r.dir, spec.total_generations(), done});
  const auto open = [&] {
    store::ResultsDb db = store::ResultsDb::open(r.dir);
    if (extend.front())
      store::RunDirectory::carry_on(r.dir, db, spec, carry_on_overrides(stored.first(), *extend.front()));
    return store::RunDirectory::resume(r.dir, std::move(db), stored.first(), point);
  };
  eval::CampaignResult result = run_experiment(spec, campaign_options(r.execution, &point), open, done, events);
  return {r.dir, {}, {{spec.name, spec, std::move(result)}}};
}

}  // namespace

Outcome resume(const ResumeRequest& r, const compiler::CompileOptions& options, Events& events) {
  return store_errors_typed([&] { return disk_full_typed(r.dir, [&] { return resume_typed(r, options, events); }); });
}

}  // namespace esc::app
