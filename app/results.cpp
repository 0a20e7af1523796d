#include "app/results.hpp"

#include <algorithm>
#include <iterator>
#include <stdexcept>

#include <fmt/format.h>

#include "runtime/report/html_report.hpp"
#include "runtime/store/export.hpp"
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

}  // namespace

std::string export_text(const std::vector<std::filesystem::path>& dirs, std::string_view table, bool csv) {
  if (!table.empty() && std::find(std::begin(kTables), std::end(kTables), table) == std::end(kTables))
    throw std::invalid_argument(fmt::format("no table `{}`: a directory exports generations, usage or metrics", table));
  const std::vector<store::StoredDirectory> all = load_all(dirs);
  if (table == "usage") return csv ? store::usage_csv(all) : store::usage_json(all).dump(2) + "\n";
  if (table == "metrics") return csv ? store::metrics_csv(all) : store::metrics_json(all).dump(2) + "\n";
  return csv ? store::export_csv(all) : store::export_json(all).dump(2) + "\n";
}

ReportFiles write_report(const std::vector<std::filesystem::path>& dirs, std::filesystem::path out) {
  const report::Report r = report::make_report(load_all(dirs));
  if (out.empty()) out = dirs.front() / "report.html";
  const std::filesystem::path figures = out.parent_path() / "figures";
  std::filesystem::create_directories(figures);
  for (const report::NamedFigure& f : r.figures) store::write_atomically(figures / f.file, f.svg);
  store::write_atomically(out, r.html);
  return {out, figures, r.figures.size()};
}

}  // namespace esc::app
