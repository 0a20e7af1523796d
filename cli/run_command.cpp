// `esc run`: an experiment or a study of a script, or the continuation of a stopped run,
// through the application layer (app/run.hpp); this file turns options into its requests
// and its outcome into the end table.
#include <fmt/format.h>

#include "app/run.hpp"
#include "cli/commands.hpp"
#include "cli/end_table.hpp"
#include "cli/library_path.hpp"
#include "cli/load.hpp"
#include "cli/terminal_events.hpp"

namespace esc::cli {

namespace {

app::Outcome resume(const RunOptions& o, app::Events& events) {
  app::ResumeRequest r;
  r.dir = o.resume;
  r.script = find_main_script(o.file);
  r.generations = o.generations;
  r.cache = o.cache;
  r.execution = {o.threads, o.runs_at_once};
  r.explain = o.verbose;
  return app::resume(r, default_compile_options(), events);
}

app::Outcome start(const RunOptions& o, app::Events& events) {
  app::RunRequest r;
  r.script = find_main_script(o.file);
  r.experiment = o.experiment;
  r.overrides = {o.runs, o.generations, o.seed, o.settings, o.controllers, o.cache};
  r.execution = {o.threads, o.runs_at_once};
  r.out = o.out;
  return app::run(r, default_compile_options(), events);
}

}  // namespace

int run_command(const RunOptions& o) {
  if (!o.resume.empty() &&
      (o.runs || o.seed || !o.settings.empty() || !o.controllers.empty() || !o.experiment.empty() || !o.out.empty())) {
    complain("esc: error: --resume continues a run with its own settings: --runs, --seed, --set, --controllers, "
             "--experiment and --out cannot be given with it (--generations G carries it on to G generations)\n");
    return kExitUsage;
  }
  if (o.resume.empty() && o.file.empty()) {
    complain("esc: error: run needs a script FILE (or --resume DIR)\n");
    return kExitUsage;
  }
  TerminalEvents events;
  const app::Outcome outcome = o.resume.empty() ? start(o, events) : resume(o, events);
  if (follower_rank() || !outcome.ran) return kExitOk;
  if (!outcome.study.empty()) {
    std::vector<ConditionResult> conditions;
    for (const app::ConditionOutcome& c : outcome.conditions) conditions.push_back({c.name, &c.spec, c.result});
    print_study_table(outcome.study, conditions);
  }
  fmt::print("\nresults: {}/summary.json (report: esc report {})\n", outcome.dir.string(), outcome.dir.string());
  return kExitOk;
}

}  // namespace esc::cli
