// The `esc` command: check, run and benchmark experiment scripts; export, report and replay
// results.
#include <exception>
#include <filesystem>
#include <new>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "cli/commands.hpp"
#include "cli/terminal_events.hpp"
#include "cli/unknown_arguments.hpp"
#include "cli/version.hpp"
#include "runtime/core/seed_text.hpp"
#include "runtime/dist/mpi_session.hpp"

int main(int argc, char** argv) {
  using namespace esc::cli;
  // Under mpirun every rank runs this same command; a plain process never starts MPI.
  const esc::dist::MpiSession mpi(argc, argv);
  if (esc::dist::launched_by_mpi() && !esc::dist::built_with_mpi()) {
    // Every rank would run the whole campaign alone, into the same directory.
    fmt::print(stderr, "esc: error: started by an MPI launcher, but this esc was built without MPI\n"
                       "help: run it without mpirun, or build esc with MPI (Debian: libopenmpi-dev, "
                       "-DESC_WITH_MPI=ON)\n");
    return kExitBadInput;
  }
  // Ranges with bounds a person can read in the error message.
  const CLI::Range kAtLeastOne(1, 1'000'000'000, "at least 1");
  const CLI::Range kThreads(0, 4096, "0 (all cores) to 4096");
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
  CLI::App app{"esc: evolutionary robotics experiments written as scripts"};
  app.require_subcommand(1);
  app.set_version_flag("--version", version_text());
  // Unknown options and surplus arguments are reported with a suggestion (unknown_arguments.hpp).
  app.allow_extras();

  std::vector<std::filesystem::path> check_files;
  auto* check = app.add_subcommand("check", "compile scripts and report every error, without running");
  check->add_option("FILE", check_files, "script files")->required();

  RunOptions run;
  auto* run_cmd = app.add_subcommand("run", "evolve the controllers of an experiment or a study and compare them");
  run_cmd->add_option("FILE", run.file, "script file (with --resume: default the stored script path)");
  run_cmd->add_option("--resume", run.resume, "continue the interrupted run in this directory");
  run_cmd->add_option("--experiment", run.experiment,
                      "experiment or study to run (default: the first declared in the file)");
  run_cmd->add_option("--runs", run.runs, "independent runs per controller")->check(kAtLeastOne);
  run_cmd->add_option("--generations", run.generations, "generations per run")->check(kAtLeastOne);
  run_cmd->add_option("--seed", run.seed, "master seed (every random stream derives from it)")->check(kSeed);
  run_cmd->add_option("--threads", run.threads, "worker threads (default: all cores)")->check(kThreads);
  run_cmd->add_option("--runs-at-once", run.runs_at_once,
                      "runs advancing together, their evaluations pooled (default: enough to keep every worker "
                      "busy; results never depend on it)")
      ->check(kAtLeastOne);
  run_cmd->add_option("--out", run.out, "output directory (default: runs/<experiment or study>-<time>)");
  run_cmd->add_option("--cache", run.cache,
                      "where experiments whose evolved controllers are used run, and are reused (default: <out>/deps)");
  run_cmd->add_flag("--verbose", run.verbose,
                    "with --resume: a refusal's details (the script's diagnostics, which files changed)");
  // One KEY=VALUE per --set, so that `--set epochs=2 FILE` leaves FILE to the command.
  run_cmd->add_option("--controllers", run.controllers,
                      "run only these compared controllers, C1,C2 (each one's results do not change)")
      ->delimiter(',');
  run_cmd->add_option("--set", run.settings, "override a setting, KEY=VALUE (e.g. epochs=2, robot.inertia=off); "
                                             "once per setting")
      ->allow_extra_args(false)
      ->check(kKeyValue);

  ExportOptions exp;
  auto* export_cmd = app.add_subcommand("export", "write run directories' results as one CSV or JSON table");
  export_cmd->add_option("DIR", exp.dirs, "run directories (experiments or studies)")->required();
  export_cmd->add_option("--format", exp.format, "csv (default: per-generation statistics) or json (everything)")
      ->check(CLI::IsMember({"csv", "json"}));
  export_cmd->add_option("--table", exp.table,
                         "usage: the steps each behavior acted, per run, generation and behavior; metrics: what each "
                         "run's optimizer reported (CMA-ES's sigma, ...) per generation (tidy tables)")
      ->check(CLI::IsMember({"usage", "metrics"}));
  export_cmd->add_option("--out", exp.out, "output file (default: standard output)");

  ReportOptions rep;
  auto* report_cmd = app.add_subcommand("report", "write one self-contained HTML report of run directories, and "
                                                  "their figures as SVG files");
  report_cmd->add_option("DIR", rep.dirs, "run directories (experiments or studies)")->required();
  report_cmd->add_option("--out", rep.out,
                         "output file (default: DIR/report.html; required for several directories); figures go "
                         "beside it in figures/");

  ReplayOptions replay;
  auto* replay_cmd = app.add_subcommand(
      "replay", "re-simulate a stored controller: an SVG of its trajectories and a CSV of every step");
  replay_cmd->add_option("SOURCE", replay.source, "run directory, or a stored genome (CONTROLLER/run-NN.best.json)")
      ->required();
  replay_cmd->add_option("--controller", replay.controller, "controller to replay (default: every one)");
  replay_cmd->add_option("--run", replay.run, "run to replay, from 1 (default: each controller's best run)")
      ->check(kAtLeastOne);
  replay_cmd->add_option("--epochs", replay.epochs, "epochs to draw and write, from 1: 1,3,5-7 (default: all)");
  replay_cmd->add_option("--out", replay.out, "output directory (default: SOURCE's directory)");
  replay_cmd->add_option("--script", replay.script,
                         "evaluate in an experiment of this script instead of the stored one (another arena, robot "
                         "or fitness)");
  replay_cmd->add_option("--experiment", replay.experiment, "experiment of --script (default: its first)");
  replay_cmd->add_option("--seed", replay.seed, "evaluation seed (default: that of the stored best evaluation)")
      ->check(kSeed);
  replay_cmd->add_flag("--animate", replay.animate,
                       "also write an animation: MP4 with ffmpeg, else GIF with ImageMagick's convert");

  BenchOptions bench;
  auto* bench_cmd = app.add_subcommand("bench", "measure control steps per second and thread scaling");
  bench_cmd->add_option("--threads", bench.max_threads, "largest thread count (default: all cores)")
      ->check(kThreads);
  bench_cmd->add_option("--min-time", bench.min_time_s, "seconds per benchmark")->check(CLI::PositiveNumber);
  bench_cmd->add_option("--campaign", bench.campaign,
                        "estimate the cost of every experiment of a script from measured rates");
  bench_cmd->add_option("--benchmark", bench.benchmark_args,
                        "arguments for Google Benchmark (--benchmark_filter=...); its items only, no fractions");
  bench_cmd->add_option("--profile", bench.profile,
                        "run one loop of the fractions alone, for a profiler: obstacle, energy, supervisor (each also "
                        "with -plain), pressed, free");
  bench_cmd->add_option("--evaluations", bench.evaluations, "items of the --profile loop (default 200)")
      ->check(CLI::PositiveNumber);

  if (unknown_command(app, argc, argv)) return kExitUsage;
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kExitOk : kExitUsage;
  }
  for (const CLI::App* command : app.get_subcommands())
    if (unexpected_arguments(*command)) return kExitUsage;
  try {
    if (*check) return check_command(check_files);
    if (*run_cmd) return run_command(run);
    if (*export_cmd) return export_command(exp);
    if (*report_cmd) return report_command(rep);
    if (*replay_cmd) return replay_command(replay);
    if (*bench_cmd) return bench_command(bench);
  } catch (const esc::app::Error& e) {
    // Every rank met it (app/ranks.hpp) and ends normally.
    print_error(e);
    return kExitBadInput;
  } catch (const std::bad_alloc&) {
    fmt::print(stderr, "esc: error: out of memory\n");
  } catch (const std::exception& e) {
    fmt::print(stderr, "esc: error: {}\n", e.what());
  }
  // The other ranks of an MPI job may be waiting for this one: end them all.
  if (mpi.active() && mpi.size() > 1) mpi.abort(kExitBadInput);
  return kExitBadInput;
}
