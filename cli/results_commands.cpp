// `esc export` and `esc report`: read run directories' databases, never change them.
#include <fstream>
#include <iostream>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "runtime/report/html_report.hpp"
#include "runtime/store/export.hpp"
#include "runtime/store/metrics_export.hpp"
#include "runtime/store/run_directory.hpp"
#include "runtime/store/usage_export.hpp"

namespace esc::cli {

namespace {

std::vector<store::StoredDirectory> load_all(const std::vector<std::filesystem::path>& dirs) {
  std::vector<store::StoredDirectory> all;
  for (const std::filesystem::path& d : dirs) all.push_back({d, store::ResultsDb::open(d, true).load()});
  return all;
}

}  // namespace

int export_command(const ExportOptions& o) {
  if (o.format != "csv" && o.format != "json") {
    fmt::print(stderr, "esc: error: --format must be csv or json, not `{}`\n", o.format);
    return kExitUsage;
  }
  const std::vector<store::StoredDirectory> all = load_all(o.dirs);
  const bool csv = o.format == "csv";
  const std::string text =
      o.table == "usage"     ? (csv ? store::usage_csv(all) : store::usage_json(all).dump(2) + "\n")
      : o.table == "metrics" ? (csv ? store::metrics_csv(all) : store::metrics_json(all).dump(2) + "\n")
      : csv                  ? store::export_csv(all)
                             : store::export_json(all).dump(2) + "\n";
  if (o.out.empty()) {
    std::cout << text << std::flush;
  } else {
    store::write_atomically(o.out, text);
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
  const report::Report r = report::make_report(load_all(o.dirs));
  const std::filesystem::path out = o.out.empty() ? o.dirs.front() / "report.html" : o.out;
  const std::filesystem::path figures = out.parent_path() / "figures";
  std::filesystem::create_directories(figures);
  for (const report::NamedFigure& f : r.figures) store::write_atomically(figures / f.file, f.svg);
  store::write_atomically(out, r.html);
  fmt::print("esc: wrote {} and {} figure{} in {}\n", out.string(), r.figures.size(), r.figures.size() == 1 ? "" : "s",
             figures.string());
  return kExitOk;
}

}  // namespace esc::cli
