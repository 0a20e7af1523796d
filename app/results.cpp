#include "app/results.hpp"

#include <algorithm>
#include <iterator>
#include <stdexcept>

#include <fmt/format.h>

#include "app/store_errors.hpp"
#include "compiler/names.hpp"
#include "runtime/report/html_report.hpp"
#include "runtime/store/export.hpp"
#include "runtime/store/members_export.hpp"
#include "runtime/store/metrics_export.hpp"
#include "runtime/store/run_directory.hpp"
#include "runtime/store/usage_export.hpp"

namespace esc::app {

namespace {

std::vector<store::StoredDirectory> load_all(const std::vector<std::filesystem::path>& dirs) {
  std::vector<store::StoredDirectory> all;
  for (const std::filesystem::path& d : dirs) all.push_back({d, store::ResultsDb::open(d, true).load()});
  return all;
}

// Empty (the default table), or one of kTables; std::invalid_argument otherwise, before any
// directory is read.
void check_table(std::string_view table) {
  if (table.empty() || std::find(std::begin(kTables), std::end(kTables), table) != std::end(kTables)) return;
  std::string message = fmt::format("no table `{}`: a directory exports generations, usage, metrics, front or archive",
                                    table);
  if (const auto near = compiler::closest(std::string(table), {std::begin(kTables), std::end(kTables)}))
    message += fmt::format("; did you mean `{}`?", *near);
  throw std::invalid_argument(message);
}

}  // namespace

std::string export_text(const std::vector<std::filesystem::path>& dirs, std::string_view table, bool csv) {
  check_table(table);
  return table_text(load_all(dirs), table, csv);
}

std::string table_text(const std::vector<store::StoredDirectory>& all, std::string_view table, bool csv) {
  check_table(table);
  if (table == "usage") return csv ? store::usage_csv(all) : store::usage_json(all).dump(2) + "\n";
  if (table == "metrics") return csv ? store::metrics_csv(all) : store::metrics_json(all).dump(2) + "\n";
  if (table == "front" || table == "archive")
    return csv ? store::members_csv(all, table) : store::members_json(all, table).dump(2) + "\n";
  return csv ? store::export_csv(all) : store::export_json(all).dump(2) + "\n";
}

ReportFiles write_report(const std::vector<std::filesystem::path>& dirs, std::filesystem::path out) {
  const report::Report r = report::make_report(load_all(dirs));
  if (out.empty()) out = dirs.front() / "report.html";
  require_writable(out.parent_path(), "the report and its figures cannot be written there",
                   fmt::format("write them elsewhere: esc report {} --out DIR2/report.html", dirs.front().string()));
  const std::filesystem::path figures = out.parent_path() / "figures";
  std::filesystem::create_directories(figures);
  for (const report::NamedFigure& f : r.figures) store::write_atomically(figures / f.file, f.svg);
  store::write_atomically(out, r.html);
  return {out, figures, r.figures.size()};
}

}  // namespace esc::app
