// `esc export` and `esc report`: read a run directory's database, never change it.
#include <fstream>
#include <iostream>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "runtime/report/html_report.hpp"
#include "runtime/store/export.hpp"
#include "runtime/store/run_directory.hpp"

namespace esc::cli {

int export_command(const ExportOptions& o) {
  if (o.format != "csv" && o.format != "json") {
    fmt::print(stderr, "esc: error: --format must be csv or json, not `{}`\n", o.format);
    return kExitUsage;
  }
  store::ResultsDb db = store::ResultsDb::open(o.dir);
  const std::vector<store::StoredExperiment> experiments = db.load();
  const std::string text = o.format == "csv" ? store::export_csv(experiments)
                                             : store::export_json(experiments).dump(2) + "\n";
  if (o.out.empty()) {
    std::cout << text << std::flush;
  } else {
    store::write_atomically(o.out, text);
    fmt::print(stderr, "esc: wrote {}\n", o.out.string());
  }
  return kExitOk;
}

int report_command(const ReportOptions& o) {
  store::ResultsDb db = store::ResultsDb::open(o.dir);
  const std::vector<store::StoredExperiment> experiments = db.load();
  const std::filesystem::path out = o.out.empty() ? o.dir / "report.html" : o.out;
  store::write_atomically(out, report::html_report(experiments));
  fmt::print("esc: wrote {}\n", out.string());
  return kExitOk;
}

}  // namespace esc::cli
