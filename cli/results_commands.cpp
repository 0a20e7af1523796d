// `esc export` and `esc report` (app/results.hpp): read run directories, never change them.
#include <iostream>

#include <fmt/format.h>

#include "app/output_files.hpp"
#include "app/results.hpp"
#include "cli/commands.hpp"
#include "cli/load.hpp"
#include "cli/terminal_events.hpp"

namespace esc::cli {

int export_command(const ExportOptions& o) {
  if (o.format != "csv" && o.format != "json") {
    fmt::print(stderr, "esc: error: --format must be csv or json, not `{}`\n", o.format);
    return kExitUsage;
  }
  TerminalEvents events;
  const compiler::CompileOptions options = default_compile_options();
  const std::string text = app::export_text(o.dirs, o.table, o.format == "csv", events, &options);
  if (o.out.empty()) {
    std::cout << text << std::flush;
  } else {
    app::write_atomically(o.out, text);
    fmt::print(stderr, "esc: wrote {}\n", o.out.string());
  }
  return kExitOk;
}

int report_command(const ReportOptions& o) {
  if (o.dirs.size() > 1 && o.out.empty()) {
    fmt::print(stderr, "esc: error: a report over {} directories needs --out FILE (where to write it; its figures go "
                       "beside it, in figures/)\n", o.dirs.size());
    return kExitUsage;
  }
  TerminalEvents events;
  const app::ReportFiles written = app::write_report(o.dirs, o.out, events);
  fmt::print("esc: wrote {} and {} figure{} in {}\n", written.html.string(), written.figure_count,
             written.figure_count == 1 ? "" : "s", written.figures.string());
  return kExitOk;
}

}  // namespace esc::cli
