#include "cli/command_line.hpp"

#include <iterator>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "app/option_ranges.hpp"
#include "app/results.hpp"

#include "runtime/core/seed_text.hpp"

namespace esc::cli {

namespace {

// Ranges with bounds a person can read in the error message (app/option_ranges.hpp: the
// Python module checks against the same).
const CLI::Range kAtLeastOne(app::kCountRange.lowest, app::kCountRange.highest, std::string(app::kCountRange.text));
const CLI::Range kThreads(app::kThreadsRange.lowest, app::kThreadsRange.highest, std::string(app::kThreadsRange.text));
// A seed is read digit by digit (seed_text.hpp): CLI11 alone wraps `-1` to 2^64 - 1.
const CLI::Validator kSeed(
    [](const std::string& text) {
      return esc::parse_seed(text) ? std::string() : fmt::format("a seed is {}, found `{}`", esc::kSeedRange, text);
    },
    "SEED");
// `--set KEY=VALUE` is command-line syntax (exit 2 when malformed); the value itself is the
// script's, checked with the experiment (exit 1 when refused).
const CLI::Validator kKeyValue(
    [](const std::string& text) {
      const auto eq = text.find('=');
      return eq != std::string::npos && eq > 0 ? std::string()
                                               : fmt::format("--set expects KEY=VALUE, got `{}`", text);
    },
    "KEY=VALUE");

}  // namespace

CLI::App* add_check(CLI::App& app, std::vector<std::filesystem::path>& files) {
  auto* const command = app.add_subcommand("check", "compile scripts and report every error, without running");
  command->add_option("FILE", files, "script files")->required();
  return command;
}

CLI::App* add_run(CLI::App& app, RunOptions& o) {
  auto* const command = app.add_subcommand("run", "evolve the controllers of an experiment or a study and compare them");
  command->add_option("FILE", o.file, "script file (with --resume: default the stored script path)");
  command->add_option("--resume", o.resume,
                      "continue the interrupted run or study in this directory, with the settings it started with "
                      "(with --generations G: carry every run on to G generations)");
  command->add_option("--experiment", o.experiment,
                      "experiment or study to run (default: the first declared in the file)");
  command->add_option("--runs", o.runs, "independent runs per controller")->check(kAtLeastOne);
  command->add_option("--generations", o.generations,
                      "generations per run (with --resume: carry a finished or stopped run on to this many)")
      ->check(kAtLeastOne);
  command->add_option("--seed", o.seed, "master seed (every random stream derives from it)")->check(kSeed);
  command->add_option("--threads", o.threads, "worker threads (default: all cores)")->check(kThreads);
  command->add_option("--runs-at-once", o.runs_at_once,
                      "runs advancing together, their evaluations pooled (default: enough to keep every worker "
                      "busy; results never depend on it)")
      ->check(kAtLeastOne);
  command->add_option("--out", o.out, "output directory (default: runs/<experiment or study>-<time>)");
  command->add_option("--cache", o.cache,
                      "where experiments whose evolved controllers are used run, and are reused (default: <out>/deps)");
  command->add_flag("--verbose", o.verbose,
                    "with --resume: a refusal's details (the script's diagnostics, which files changed)");
  // One KEY=VALUE per --set, so that `--set epochs=2 FILE` leaves FILE to the command.
  command->add_option("--controllers", o.controllers,
                      "run only these compared controllers, C1,C2 (each one's results do not change)")
      ->delimiter(',');
  command->add_option("--set", o.settings, "override a setting, KEY=VALUE (e.g. epochs=2, robot.inertia=off); "
                                             "once per setting")
      ->allow_extra_args(false)
      ->check(kKeyValue);
  return command;
}

CLI::App* add_export(CLI::App& app, ExportOptions& o) {
  auto* const command = app.add_subcommand("export", "write run directories' results as one CSV or JSON table");
  command->add_option("DIR", o.dirs, "run directories (experiments or studies)")->required();
  command->add_option("--format", o.format, "csv (default: per-generation statistics) or json (everything)")
      ->check(CLI::IsMember({"csv", "json"}));
  command->add_option("--table", o.table,
                         "usage: the steps each behavior acted, per run, generation and behavior; metrics: what each "
                         "run's optimizer reported (CMA-ES's sigma, ...) per generation; front: NSGA-II's first front "
                         "per generation; archive: MAP-Elites' and novelty search's archive changes per generation; "
                         "success: Fisher's and the censored Mann-Whitney test of each pair the end table compares; "
                         "comparisons: the end table's tests of best fitness (Welch, Mann-Whitney, A12, "
                         "Brown-Forsythe, Holm), a row per pair; "
                         "topology: the nodes and links of each run's best NEAT network and of its final front's or archive's (tidy tables)")
      ->check(CLI::IsMember(std::vector<std::string>(std::begin(app::kTables), std::end(app::kTables))));
  command->add_option("--out", o.out, "output file (default: standard output)");
  return command;
}

CLI::App* add_report(CLI::App& app, ReportOptions& o) {
  auto* const command = app.add_subcommand("report", "write one self-contained HTML report of run directories, and "
                                                  "their figures as SVG files");
  command->add_option("DIR", o.dirs, "run directories (experiments or studies)")->required();
  command->add_option("--out", o.out,
                         "output file (default: DIR/report.html; required for several directories); figures go "
                         "beside it in figures/");
  return command;
}

CLI::App* add_replay(CLI::App& app, ReplayOptions& o) {
  auto* const command = app.add_subcommand(
      "replay", "re-simulate a stored controller: an SVG of its trajectories and a CSV of every step");
  command->add_option("SOURCE", o.source, "run directory, or a stored genome (CONTROLLER/run-NN.best.json)")
      ->required();
  command->add_option("--controller", o.controller, "controller to replay (default: every one)");
  command->add_option("--run", o.run, "run to replay, from 1 (default: each controller's best run)")
      ->check(kAtLeastOne);
  command->add_option("--epochs", o.epochs, "epochs to draw and write, from 1: 1,3,5-7 (default: all)");
  command->add_option("--out", o.out, "output directory (default: SOURCE's directory)");
  command->add_option("--script", o.script,
                         "evaluate in an experiment of this script instead of the stored one (another arena, robot "
                         "or fitness)");
  command->add_option("--experiment", o.experiment, "experiment of --script (default: its first)");
  command->add_option("--seed", o.seed, "evaluation seed (default: that of the stored best evaluation)")
      ->check(kSeed);
  command->add_option("--member", o.member,
                         "replay a member of the run's final Pareto front (its position, from 0) or archive (its "
                         "cell; `esc export --table front|archive` lists them) instead of its best")
      ->check(CLI::NonNegativeNumber);
  command->add_flag("--animate", o.animate,
                       "also write an animation: MP4 with ffmpeg, else GIF with ImageMagick's convert");
  command->add_flag("--evaluations", o.evaluations,
                    "make the whole run again from its seed (checked against the stored one) and write every "
                    "evaluation's objectives and descriptors (CSV) and where they fall over the first two "
                    "descriptors (SVG)");
  command->add_flag("--arena", o.over_arena,
                    "with --evaluations: draw the arena over the first two descriptors, read as the robot's x and y");
  command->add_option("--threads", o.threads, "with --evaluations: worker threads (default: all cores)")
      ->check(kThreads);
  return command;
}

CLI::App* add_bench(CLI::App& app, BenchOptions& o) {
  auto* const command = app.add_subcommand("bench", "measure control steps per second and thread scaling");
  command->add_option("--threads", o.max_threads, "largest thread count (default: all cores)")
      ->check(kThreads);
  command->add_option("--min-time", o.min_time_s, "seconds per benchmark")->check(CLI::PositiveNumber);
  command->add_option("--campaign", o.campaign,
                        "estimate the cost of every experiment of a script from measured rates");
  command->add_option("--benchmark", o.benchmark_args,
                        "arguments for Google Benchmark (--benchmark_filter=...); its items only, no fractions");
  command->add_option("--profile", o.profile,
                        "run one loop of the fractions alone, for a profiler: obstacle, energy, supervisor (each also "
                        "with -plain), pressed, free");
  command->add_option("--evaluations", o.evaluations, "items of the --profile loop (default 200)")
      ->check(CLI::PositiveNumber);
  return command;
}

}  // namespace esc::cli
