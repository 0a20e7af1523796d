// The `esc` command: check, run and benchmark experiment scripts; export, report and replay
// results.
#include <exception>
#include <filesystem>
#include <new>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "cli/command_line.hpp"
#include "cli/commands.hpp"
#include "cli/terminal_events.hpp"
#include "cli/unknown_arguments.hpp"
#include "cli/version.hpp"
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
  CLI::App app{"esc: evolutionary robotics experiments written as scripts"};
  app.require_subcommand(1);
  app.set_version_flag("--version", version_text());
  // Unknown options and surplus arguments are reported with a suggestion (unknown_arguments.hpp).
  app.allow_extras();
  // A command line CLI11 refuses reads like every other refusal: `esc: error:` and where to
  // look next.
  app.failure_message([](const CLI::App* root, const CLI::Error& e) {
    const auto parsed = root->get_subcommands();
    return fmt::format("esc: error: {}\n{}\n", e.what(),
                       parsed.empty() ? std::string("run `esc --help` for the commands and their options")
                                      : fmt::format("run `esc {} --help` for its arguments and options",
                                                    parsed.front()->get_name()));
  });

  std::vector<std::filesystem::path> check_files;
  RunOptions run;
  ExportOptions exp;
  ReportOptions rep;
  ReplayOptions replay;
  BenchOptions bench;
  const CLI::App* check = add_check(app, check_files);
  const CLI::App* run_cmd = add_run(app, run);
  const CLI::App* export_cmd = add_export(app, exp);
  const CLI::App* report_cmd = add_report(app, rep);
  const CLI::App* replay_cmd = add_replay(app, replay);
  const CLI::App* bench_cmd = add_bench(app, bench);

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
