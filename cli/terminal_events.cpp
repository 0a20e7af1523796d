#include "cli/terminal_events.hpp"

#include <iostream>

#include <unistd.h>

#include "cli/end_table.hpp"
#include "cli/interrupt.hpp"
#include "cli/load.hpp"
#include "cli/progress.hpp"

namespace esc::cli {

namespace {

void print_diagnostics(const compiler::CompileResult& compiled) {
  // Rendered source lines go out as they are (complain() would shorten `quoted` names).
  if (!follower_rank()) std::cerr << compiler::render_all(compiled.diagnostics, compiled.sources, isatty(STDERR_FILENO) != 0);
}

}  // namespace

void TerminalEvents::warnings(const compiler::CompileResult& compiled) { print_diagnostics(compiled); }

void TerminalEvents::note(const app::Note& note) {
  if ((note.kind == app::Note::Kind::Start || note.kind == app::Note::Kind::Resume) && !follower_rank())
    on_interrupt_name(note.dir, note.generations, note.generations_stored, note.restart);
  if (note.kind == app::Note::Kind::Warning)
    complain("esc: {}\n", note.text);
  else
    say("esc: {}\n", note.text);
}

std::unique_ptr<app::Progress> TerminalEvents::progress(const eval::ExperimentSpec& spec, const std::string&,
                                                        eval::CampaignListener& next, std::int64_t already_done) {
  return std::make_unique<ProgressPrinter>(spec, next, isatty(STDOUT_FILENO) != 0, already_done);
}

void TerminalEvents::experiment_done(const eval::ExperimentSpec& spec, const eval::CampaignResult& result) {
  print_table(spec, result);
}

void print_error(const app::Error& error) {
  for (const app::Problem& p : error.problems()) {
    complain("esc: error: {}\n", p.message);
    if (!p.help.empty()) complain("help: {}\n", p.help);
  }
  for (const std::string& line : error.details()) complain("{}\n", line);
  if (error.script() != nullptr) print_diagnostics(*error.script());
}

}  // namespace esc::cli
