#include "app/results.hpp"

#include <algorithm>
#include <iterator>
#include <stdexcept>

#include <fmt/format.h>

#include "app/store_errors.hpp"
#include "app/stored_run.hpp"
#include "runtime/control/graph_architecture.hpp"
#include "runtime/evo/registry.hpp"
#include "compiler/names.hpp"
#include "runtime/report/html_report.hpp"
#include "runtime/report/comparison_table.hpp"
#include "runtime/report/success_table.hpp"
#include "runtime/store/export.hpp"
#include "runtime/store/members_export.hpp"
#include "runtime/store/metrics_export.hpp"
#include "runtime/store/run_directory.hpp"
#include "runtime/store/topology_export.hpp"
#include "runtime/store/untouched_load.hpp"
#include "runtime/store/usage_export.hpp"

namespace esc::app {

namespace {

namespace fs = std::filesystem;

// A run directory, or one condition of a study named by its directory (STUDY/CONDITION, as
// `esc replay` takes it): that condition's experiment alone, under the study's directory.
store::StoredDirectory load(const fs::path& named, Events& events) {
  const RunLocation at = locate_run(named);
  std::vector<store::StoredExperiment> all = read_stored(at, named, events);
  if (at.condition.empty()) return {named, std::move(all)};
  std::vector<store::StoredExperiment> condition;
  for (store::StoredExperiment& e : all)
    if (e.condition && e.condition->directory == at.condition) condition.push_back(std::move(e));
  if (condition.empty())
    throw store::StoreError(fmt::format("`{}` is a directory of run `{}`, not a run or a study's condition: "
                                        "name the run, `{}`", named.string(), at.root.string(), at.root.string()));
  return {at.root, std::move(condition)};
}

std::vector<store::StoredDirectory> load_all(const std::vector<fs::path>& dirs, Events& events) {
  std::vector<store::StoredDirectory> all;
  for (const fs::path& d : dirs) all.push_back(load(d, events));
  return all;
}

// Empty (the default table), or one of kTables; std::invalid_argument otherwise, before any
// directory is read.
void check_table(std::string_view table) {
  if (table.empty() || std::find(std::begin(kTables), std::end(kTables), table) != std::end(kTables)) return;
  std::string message = fmt::format("no table `{}`: a directory exports generations, usage, metrics, front, archive, success, comparisons or topology",
                                    table);
  if (const auto near = compiler::closest(std::string(table), {std::begin(kTables), std::end(kTables)}))
    message += fmt::format("; did you mean `{}`?", *near);
  throw std::invalid_argument(message);
}

}  // namespace

RunLocation locate_run(fs::path dir) {
  std::error_code ec;
  if (dir.filename().empty()) dir = dir.parent_path();   // "DIR/"
  if (fs::exists(dir / store::kDatabaseFile, ec)) return {dir, {}, true};
  const fs::path parent = dir.parent_path().empty() ? fs::path(".") : dir.parent_path();
  if (!dir.filename().empty() && fs::exists(parent / store::kDatabaseFile, ec))
    return {parent, dir.filename().string(), true};
  return {dir, {}, false};
}

std::vector<store::StoredExperiment> read_stored(const RunLocation& at, const fs::path& named, Events& events) {
  store::ResultsDb db = store::ResultsDb::open(at.condition.empty() ? named : at.root, true);
  if (db.log_damage()) events.note({Note::Kind::Warning, log_damage_warning(at.root, *db.log_damage())});
  return db.load();
}

store::StoredExperiment read_single(const fs::path& dir) { return store::ResultsDb::open(dir, true).load_single(); }

store::StoredDirectory read_untouched(const fs::path& dir, Events& events) {
  store::UntouchedRead read = store::read_untouched(dir);
  if (read.log_damage) events.note({Note::Kind::Warning, log_damage_warning(dir, *read.log_damage)});
  return {dir, std::move(read.experiments)};
}

std::string log_damage_warning(const std::filesystem::path& root, const store::LogScan& scan) {
  return fmt::format("{}: the generations they held are not read; `esc run --resume {}` runs them again",
                     store::log_damage_text(root / store::kDatabaseFile, scan), root.string());
}

std::string export_text(const std::vector<std::filesystem::path>& dirs, std::string_view table, bool csv,
                        Events& events, const compiler::CompileOptions* options) {
  check_table(table);
  return table_text(load_all(dirs, events), table, csv, options);
}

namespace {

// The final fronts' and archives' networks of the NEAT networks that another algorithm than
// NEAT evolved (NEAT keeps no genomes beside its best), each experiment compiled once from
// the sources its run stored.
std::vector<store::RunMembers> graph_members(const std::vector<store::StoredDirectory>& all,
                                             const compiler::CompileOptions& options) {
  std::vector<store::RunMembers> out;
  for (const store::StoredDirectory& d : all)
    for (const store::StoredExperiment& e : d.experiments) {
      const auto keeps = [](const store::StoredController& c) {
        const evo::Algorithm* a = evo::find_algorithm(c.algorithm);
        return control::is_graph_architecture(c.architecture) && a != nullptr &&
               a->name != eval::ExperimentSpec::kDefaultGraphs;
      };
      if (std::none_of(e.controllers.begin(), e.controllers.end(), keeps)) continue;
      // A study's condition directory (STUDY/CONDITION) is read from its study's database.
      const StoredRun stored{&e, locate_run(d.path).root, d.path};
      Events quiet;   // the script's warnings were the run's, given when it ran
      const eval::ExperimentSpec spec = experiment_of_run(stored, options, quiet);
      for (const store::StoredController& c : e.controllers) {
        if (!keeps(c)) continue;
        for (const eval::RunResult& r : c.finished) {
          const evo::Members kept = final_members(stored, spec, c.name, r.run);
          store::RunMembers m{e.name, e.condition ? e.condition->name : std::string(), c.name, r.run + 1,
                              kept.kind == evo::MemberKind::Front ? "front" : "archive", {}};
          for (const evo::Member& member : kept.members)
            if (!member.genome.empty()) m.genomes.emplace_back(member.cell, member.genome);
          if (!m.genomes.empty()) out.push_back(std::move(m));
        }
      }
    }
  return out;
}

}  // namespace

std::string table_text(const std::vector<store::StoredDirectory>& all, std::string_view table, bool csv,
                       const compiler::CompileOptions* options) {
  check_table(table);
  if (table == "usage") return csv ? store::usage_csv(all) : store::usage_json(all).dump(2) + "\n";
  if (table == "metrics") return csv ? store::metrics_csv(all) : store::metrics_json(all).dump(2) + "\n";
  if (table == "topology") {
    const std::vector<store::RunMembers> members =
        options != nullptr ? graph_members(all, *options) : std::vector<store::RunMembers>{};
    return csv ? store::topology_csv(all, members) : store::topology_json(all, members).dump(2) + "\n";
  }
  if (table == "success") {
    const std::vector<report::SuccessRow> rows = report::success_rows(all);
    return csv ? report::success_csv(rows) : report::success_json(rows).dump(2) + "\n";
  }
  if (table == "comparisons") {
    const std::vector<report::ComparisonRow> rows = report::comparison_rows(all);
    return csv ? report::comparisons_csv(rows) : report::comparisons_json(rows).dump(2) + "\n";
  }
  if (table == "front" || table == "archive")
    return csv ? store::members_csv(all, table) : store::members_json(all, table).dump(2) + "\n";
  return csv ? store::export_csv(all) : store::export_json(all).dump(2) + "\n";
}

ReportFiles write_report(const std::vector<std::filesystem::path>& dirs, std::filesystem::path out, Events& events) {
  const report::Report r = report::make_report(load_all(dirs, events));
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
