// `esc run`: an experiment or a study of a script, or the continuation of a stopped run.
#include <optional>
#include <variant>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "cli/controller_selection.hpp"
#include "cli/dependencies.hpp"
#include "cli/end_table.hpp"
#include "cli/load.hpp"
#include "cli/run_support.hpp"
#include "runtime/store/run_directory.hpp"
#include "runtime/store/untouched_load.hpp"

namespace esc::cli {

namespace {

// Runs the campaign into the directory `open` makes (on rank 0), then prints its table.
int run_experiment(const eval::ExperimentSpec& spec, const eval::CampaignOptions& options,
                   const std::function<store::RunDirectory()>& open, std::int64_t already_done,
                   const std::filesystem::path& out) {
  std::optional<store::RunDirectory> dir;
  if (!open_on_rank0([&] { dir.emplace(open()); })) return kExitBadInput;
  const eval::CampaignResult result = campaign_on_all_ranks(spec, options, dir ? &*dir : nullptr, already_done);
  if (follower_rank()) return kExitOk;
  print_table(spec, result);
  fmt::print("\nresults: {}/summary.json (report: esc report {})\n", out.string(), out.string());
  return kExitOk;
}

int resume_command(const RunOptions& o) {
  if (o.runs || o.seed || !o.settings.empty() || !o.controllers.empty() || !o.experiment.empty() || !o.out.empty()) {
    complain("esc: error: --resume continues a run with its own settings: --runs, --seed, --set, --controllers, "
             "--experiment and --out cannot be given with it (--generations G carries it on to G generations)\n");
    return kExitUsage;
  }
  // Held from the start (rank 0 writes): a run still writing into the directory refuses
  // this one before anything is read or printed.
  std::shared_ptr<const store::DirectoryLock> lock;
  std::error_code ec;
  if (!follower_rank() && std::filesystem::is_directory(o.resume, ec)) {
    try {
      lock = store::DirectoryLock::acquire(o.resume);
    } catch (const store::StoreError& e) {
      complain("esc: error: {}\n", e.what());
      return kExitBadInput;
    }
  }
  // Every check reads a copy: a refused resume leaves every byte of the directory as it was.
  std::vector<store::StoredExperiment> all;
  try {
    all = store::load_untouched(o.resume);
  } catch (const store::NothingStored& e) {
    complain("esc: error: {}; nothing was stored to resume: start it again with `esc run FILE --out {}` (finished "
             "dependencies in its deps/ are reused)\n",
             e.what(), o.resume.string());
    return kExitBadInput;
  }
  if (!all.empty() && all.front().condition) return resume_study(o, std::move(all));
  if (all.size() != 1) {
    complain("esc: error: {} holds {} experiments; a run directory holds one\n", o.resume.string(), all.size());
    return kExitBadInput;
  }
  const store::StoredExperiment stored = std::move(all.front());
  const auto complete = [&] {
    say("esc: {} is complete ({} x {} runs x {} generations); nothing to resume\n", o.resume.string(),
        stored.controllers.size(), stored.runs, stored.generations);
    return kExitOk;
  };
  if (stored.finished() && !o.generations) return complete();
  const auto script = resume_script(o, stored.script);
  if (!script) return kExitBadInput;
  compiler::CompileResult compiled = compile_to_resume(o, *script);
  if (!compiled.ok()) return kExitBadInput;
  eval::ExperimentSpec* const stored_spec = pick_stored_experiment(compiled, *script, stored.name);
  if (stored_spec == nullptr) return kExitBadInput;
  eval::ExperimentSpec& spec = *stored_spec;
  // The settings it was launched with, for it and its dependencies.
  RunOptions replay = stored_overrides(stored, o.resume);
  if (!apply_overrides(replay, spec) || !select_controllers(replay.controllers, spec) ||
      !fits_in_memory(spec))
    return kExitBadInput;
  replay.threads = o.threads;
  replay.runs_at_once = o.runs_at_once;
  // As stored: with the generations a previous --generations carried it on to, if any.
  const std::optional<int> carried = stored_carry_on(stored, o.resume);
  eval::ExperimentSpec as_stored = spec;
  if (!set_generations(as_stored, carried)) {
    complain("esc: error: {} is damaged: it was carried on to {} generations\n", o.resume.string(), *carried);
    return kExitBadInput;
  }
  if (!resumable(as_stored, sources_of(compiled), stored, *script, o)) return kExitBadInput;
  const std::optional<int> extend = carry_on_to(o, as_stored);
  if (extend && *extend < 0) return kExitBadInput;
  if (!extend && stored.finished()) return complete();
  if (is_cache_entry(o.resume)) {
    // Its dependents would read the longer run under the fingerprint of the shorter.
    complain("esc: error: {} is an entry of a dependency cache, which its dependents read as it was made; "
             "to carry it on, copy it elsewhere without its {} and give --cache {}\n",
             o.resume.string(), kFingerprintFile, o.resume.parent_path().string());
    return kExitBadInput;
  }
  // Dependencies last: a script that cannot resume should not first run them. They, and what
  // the run received from them, are checked with the generations it was launched with:
  // carrying a run on extends it alone.
  const std::filesystem::path cache = resume_cache(o, replay);
  if (!prepare_dependencies(spec, dependency_context(compiled, replay, cache, *script))) return kExitBadInput;
  if (!same_inputs(spec, stored, cache, o.resume)) return kExitBadInput;
  (void)set_generations(spec, extend ? extend : carried);

  // Read from a copy too: a carry-on refused here leaves the directory as it was.
  const eval::ResumePoint point = std::move(store::resume_points_untouched(o.resume, {&stored}, {&spec}).front());
  const std::int64_t done = generations_done(point);
  if (extend)
    say("esc: carrying {} in {} on to {} generations: {} of {} generations done\n", spec.name, o.resume.string(),
        *extend, done, spec.total_generations());
  else
    say("esc: resuming {} in {}: {} of {} generations done\n", spec.name, o.resume.string(), done,
        spec.total_generations());
  return run_experiment(
      spec, campaign_options(o, &point),
      [&] {
        store::ResultsDb db = store::ResultsDb::open(o.resume);
        if (extend) {
          nlohmann::ordered_json overrides = stored.overrides;
          overrides["carry_on"] = *extend;
          store::RunDirectory::carry_on(o.resume, db, spec, overrides);
        }
        return store::RunDirectory::resume(o.resume, std::move(db), stored, point);
      },
      done, o.resume);
}

}  // namespace

int run_command(const RunOptions& o) {
  if (!o.resume.empty()) return resume_command(o);
  if (o.file.empty()) {
    complain("esc: error: run needs a script FILE (or --resume DIR)\n");
    return kExitUsage;
  }
  compiler::CompileResult compiled = load_script(o.file);
  if (!compiled.ok()) return kExitBadInput;
  const Target target = pick_target(compiled, o.file, o.experiment);
  if (std::holds_alternative<eval::StudySpec*>(target)) return run_study(o, compiled, *std::get<eval::StudySpec*>(target));
  if (!std::holds_alternative<eval::ExperimentSpec*>(target)) return kExitBadInput;
  eval::ExperimentSpec& spec = *std::get<eval::ExperimentSpec*>(target);
  if (!apply_overrides(o, spec) || !select_controllers(o.controllers, spec) || !fits_in_memory(spec))
    return kExitBadInput;

  const std::filesystem::path out = o.out.empty() ? default_out(spec.name) : o.out;
  if (!prepare_dependencies(spec, dependency_context(compiled, o, run_cache(o, out), o.file)))
    return kExitBadInput;
  const store::LaunchInfo launch = launch_info(o, o.file, &spec);
  const auto open = [&] {
    store::RunDirectory dir(out, spec, sources_of(compiled), launch);
    fmt::print("esc: running {} ({} controller{}, {} run{}, {}) into {}\n", spec.name, spec.controllers.size(),
               spec.controllers.size() == 1 ? "" : "s", spec.runs, spec.runs == 1 ? "" : "s", generations_text(spec),
               out.string());
    return dir;
  };
  return run_experiment(spec, campaign_options(o, nullptr), open, 0, out);
}

}  // namespace esc::cli
