// Everything a results database holds read back (ResultsDb::load and what it builds on), in
// whichever schema it was written, and where a resume picks it up.
#include <algorithm>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "runtime/store/analysis_tables.hpp"
#include "runtime/store/es_state.hpp"
#include "runtime/store/member_tables.hpp"
#include "runtime/store/metric_tables.hpp"
#include "runtime/store/optimizer_tables.hpp"
#include "runtime/store/results_db.hpp"
#include "runtime/store/row_checksum.hpp"
#include "runtime/store/trace_rows.hpp"
#include "runtime/store/tree_state.hpp"

namespace esc::store {

namespace {

std::uint64_t parse_u64(const std::string& s, const char* what) {
  try {
    std::size_t used = 0;
    const unsigned long long v = std::stoull(s, &used);
    if (used != s.size()) throw std::invalid_argument(s);
    return v;
  } catch (const std::exception&) {
    throw StoreError(fmt::format("the database is damaged: {} `{}` is not a number", what, s));
  }
}

}  // namespace

std::vector<StoredExperiment> ResultsDb::load() {
  try {
    // Nothing stored is used before every row is known to be as written (older schemas
    // carry no checksums: opening one for writing seals it as it is).
    if (schema_version_ >= 5) verify_rows(db_, file_);
    std::vector<StoredExperiment> out;
    auto ex = db_.prepare(
        "SELECT id, name, seed, content_hash, status, created, software_version, script_path, overrides, arena, "
        "robot_radius_m, runs, generations, epochs, steps FROM experiments ORDER BY id");
    while (ex.step()) {
      StoredExperiment e;
      e.id = ex.int64(0);
      e.name = ex.text(1);
      e.seed = parse_u64(ex.text(2), "experiment seed");
      e.content_hash = ex.text(3);
      e.status = ex.text(4);
      e.created = ex.text(5);
      e.software_version = ex.text(6);
      e.script = ex.text(7);
      e.overrides = nlohmann::ordered_json::parse(ex.text(8));
      e.arena = nlohmann::ordered_json::parse(ex.text(9));
      e.robot_radius_m = ex.real(10);
      e.runs = ex.integer(11);
      e.generations = ex.integer(12);
      e.epochs = ex.integer(13);
      e.steps = ex.integer(14);
      out.push_back(std::move(e));
    }
    for (StoredExperiment& e : out) {
      auto src = db_.prepare("SELECT name, text FROM sources WHERE experiment_id = ? ORDER BY idx");
      src.bind(1, e.id);
      while (src.step()) e.sources.push_back({src.text(0), src.text(1)});
      auto set = db_.prepare("SELECT key, value FROM settings WHERE experiment_id = ?");
      set.bind(1, e.id);
      while (set.step()) e.settings[set.text(0)] = set.text(1);
      if (schema_version_ >= 3) load_condition(e);
      auto ctl = db_.prepare(
          fmt::format("SELECT id, name, architecture, genome_size, head, actions, {} FROM controllers "
                      "WHERE experiment_id = ? ORDER BY idx",
                      schema_version_ >= 7 ? "algorithm" : "NULL"));
      ctl.bind(1, e.id);
      while (ctl.step()) {
        StoredController c;
        c.id = ctl.int64(0);
        c.name = ctl.text(1);
        c.architecture = ctl.text(2);
        c.genome_size = static_cast<std::size_t>(ctl.int64(3));
        c.head = ctl.text(4);
        c.actions = nlohmann::json::parse(ctl.text(5)).get<std::vector<std::string>>();
        c.algorithm = !ctl.is_null(6) ? ctl.text(6) : algorithm_before_7(c);
        if (schema_version_ >= kAnalysisSchemaVersion) c.choices = load_choices(db_, c.id);
        e.controllers.push_back(std::move(c));
      }
      const bool metrics_in_rows = schema_version_ >= kMetricSchemaVersion;
      for (StoredController& c : e.controllers) {
        const MetricNames metric_names = metrics_in_rows ? MetricNames(db_, c.id) : MetricNames();
        auto runs = db_.prepare(fmt::format(
            "SELECT run, seed, status, generations_done, best_fitness, best_generation, best_index, best_genome, "
            "best_tree, {}, {}, {} FROM runs WHERE controller_id = ? ORDER BY run",
            schema_version_ >= 2 ? "best_behavior" : "NULL", schema_version_ >= 7 ? "stopped" : "NULL",
            schema_version_ >= 8 ? "success_evaluation" : "NULL"));
        runs.bind(1, c.id);
        while (runs.step()) {
          const int run = runs.integer(0);
          std::vector<eval::GenerationStats> gens;
          auto g = db_.prepare(
              fmt::format("SELECT generation, best, mean, sd, evaluations, steps, seconds, {}, {} FROM generations "
                          "WHERE controller_id = ? AND run = ? ORDER BY generation",
                          has_saturated_ ? "saturated" : "0", metrics_in_rows ? "metric_names, metrics" : "NULL, NULL"));
          g.bind(1, c.id).bind(2, run);
          const std::string damaged = fmt::format("{} is damaged: run {} of {}", file_.string(), run + 1, c.name);
          while (g.step()) {
            gens.push_back({g.integer(0), g.real(1), g.real(2), g.real(3), g.int64(4), g.int64(5), g.real(6), {}, g.int64(7)});
            if (!g.is_null(8)) gens.back().metrics = metric_names.decode(g.text(8), g.doubles(9), damaged);
          }
          const auto done = static_cast<std::size_t>(runs.int64(3));
          bool contiguous = gens.size() == done;
          for (std::size_t i = 0; contiguous && i < gens.size(); ++i) contiguous = gens[i].generation == static_cast<int>(i);
          if (!contiguous)
            throw StoreError(fmt::format("{} is damaged: run {} of {} has {} generations stored, {} expected",
                                         file_.string(), run + 1, c.name, gens.size(), done));
          std::optional<eval::Transfer> transfer;
          if (schema_version_ >= kAnalysisSchemaVersion) {
            load_usage(db_, c.id, run, gens, damaged);
            transfer = load_transfer(db_, c.id, run);
          }
          if (schema_version_ >= 6 && !metrics_in_rows) load_legacy_metrics(db_, c.id, run, gens, damaged);
          const bool has_best = !runs.is_null(4);
          const auto success = runs.is_null(11) ? std::nullopt : std::optional<std::int64_t>(runs.int64(11));
          if (runs.text(2) == "finished") {
            eval::RunResult r;
            r.run = run;
            r.seed = parse_u64(runs.text(1), "run seed");
            r.generations = std::move(gens);
            r.best_fitness = runs.real(4);
            r.best_generation = runs.integer(5);
            r.best_index = runs.integer(6);
            r.best_genome = runs.doubles(7);
            if (!runs.is_null(8)) r.best_tree = runs.text(8);
            if (!runs.is_null(9)) r.best_behavior = runs.text(9);
            if (!runs.is_null(10)) r.stopped = runs.text(10);
            r.transfer = std::move(transfer);
            r.success_evaluation = success;
            auto u = db_.prepare("SELECT steps FROM behavior_usage WHERE controller_id = ? AND run = ? ORDER BY action_idx");
            u.bind(1, c.id).bind(2, run);
            while (u.step()) r.action_usage.push_back(u.int64(0));
            c.finished.push_back(std::move(r));
          } else {
            eval::RunState s;
            s.run = run;
            s.seed = parse_u64(runs.text(1), "run seed");
            s.generations = std::move(gens);
            s.has_best = has_best;
            if (has_best) {
              s.best_fitness = runs.real(4);
              s.best_generation = runs.integer(5);
              s.best_index = runs.integer(6);
              s.best_genome = runs.doubles(7);
            }
            s.optimizer = load_state(c, run);
            s.transfer = std::move(transfer);
            s.success_evaluation = success;
            c.in_progress.push_back(std::move(s));
          }
        }
        auto rp = db_.prepare("SELECT run, seed, fitness, trace, columns FROM replays WHERE controller_id = ?");
        rp.bind(1, c.id);
        if (rp.step()) {
          const auto columns = nlohmann::json::parse(rp.text(4)).get<std::vector<std::string>>();
          c.replay = StoredReplay{rp.integer(0), parse_u64(rp.text(1), "replay seed"), rp.real(2),
                                  unpack_trace(rp.doubles(3), columns),
                                  std::find(columns.begin(), columns.end(), kRunningFitness) != columns.end()};
        }
        if (schema_version_ >= kMemberSchemaVersion)
          c.members = load_members(db_, c.id, schema_version_ >= kPackedMemberSchemaVersion,
                                   fmt::format("{} is damaged: {}", file_.string(), c.name));
      }
    }
    return out;
  } catch (const sql::SqliteError& e) {
    throw StoreError(fmt::format("{} is damaged: {}", file_.string(), e.what()));
  } catch (const nlohmann::json::exception& e) {
    throw StoreError(fmt::format("{} is damaged: {}", file_.string(), e.what()));
  }
}

std::string ResultsDb::algorithm_before_7(const StoredController& c) {
  if (schema_version_ == 6) {   // the algorithm that saved a run's state
    auto q = db_.prepare("SELECT algorithm FROM optimizer_state WHERE controller_id = ? LIMIT 1");
    q.bind(1, c.id);
    if (q.step()) return q.text(0);
  }
  return c.head == "tree" ? "gp" : "es";   // before schema 6, only the ES and GP
}

std::optional<eval::OptimizerState> ResultsDb::find_state(const StoredController& c, int run) {
  const std::string damaged = fmt::format("{} is damaged: run {} of {}", file_.string(), run + 1, c.name);
  if (schema_version_ >= 6)
    if (auto s = load_optimizer_state(db_, c.id, run, schema_version_ >= kCompressedStateSchemaVersion, damaged))
      return s;
  if (auto es = load_es_state(db_, c.id, run, c.genome_size, damaged)) return es;
  if (schema_version_ >= 2)   // a schema-1 database holds no trees
    if (auto gp = load_tree_state(db_, c.id, run, damaged)) return gp;
  return std::nullopt;
}

eval::OptimizerState ResultsDb::load_state(const StoredController& c, int run) {
  if (auto s = find_state(c, run)) return std::move(*s);
  throw StoreError(fmt::format("{} is damaged: run {} of {} is unfinished but has no state to resume from",
                               file_.string(), run + 1, c.name));
}

void ResultsDb::load_condition(StoredExperiment& e) {
  auto c = db_.prepare(
      "SELECT s.name, s.seed, c.idx, c.name, c.directory, c.sweep FROM conditions c JOIN studies s ON s.id = c.study_id "
      "WHERE c.experiment_id = ?");
  c.bind(1, e.id);
  if (!c.step()) return;
  StoredCondition sc;
  sc.study = c.text(0);
  sc.study_seed = parse_u64(c.text(1), "study seed");
  sc.index = c.integer(2);
  sc.name = c.text(3);
  sc.directory = c.text(4);
  if (!c.is_null(5)) sc.sweep = c.integer(5);
  auto set = db_.prepare(
      "SELECT key, value, swept, x, x_unit FROM condition_settings WHERE experiment_id = ? ORDER BY idx");
  set.bind(1, e.id);
  while (set.step()) {
    eval::ConditionSetting st{set.text(0), set.text(1), set.integer(2) != 0, std::nullopt, set.text(4)};
    if (!set.is_null(3)) st.x = set.real(3);
    sc.settings.push_back(std::move(st));
  }
  e.condition = std::move(sc);
}

StoredExperiment ResultsDb::load_single() {
  std::vector<StoredExperiment> all = load();
  if (!all.empty() && all.front().condition)
    throw StoreError(fmt::format("{} holds study `{}`, not one experiment", file_.string(), all.front().condition->study));
  if (all.size() != 1)
    throw StoreError(fmt::format("{} holds {} experiments; a run directory holds one", file_.string(), all.size()));
  return std::move(all.front());
}

eval::CampaignResult StoredExperiment::result() const {
  eval::CampaignResult r;
  r.experiment = name;
  r.seed = seed;
  if (const auto it = settings.find("success"); it != settings.end()) r.success = it->second;
  // Resolved only for a group, and several roles (experiment_settings.cpp): a robot alone has none.
  if (const auto it = settings.find("robots"); it != settings.end()) r.robots = std::atoi(it->second.c_str());
  if (const auto it = settings.find("roles"); it != settings.end()) r.roles = std::atoi(it->second.c_str());
  if (const auto it = settings.find("bodies"); it != settings.end()) r.bodies = it->second;
  for (const StoredController& c : controllers) {
    if (c.finished.empty()) continue;
    r.controllers.push_back({c.name, c.architecture, c.genome_size, c.finished, c.actions});
  }
  return r;
}

eval::ResumePoint ResultsDb::resume_point(const StoredExperiment& stored, const eval::ExperimentSpec& spec) {
  eval::ResumePoint p;
  for (const StoredController& c : stored.controllers) {
    const auto compared = std::find_if(spec.controllers.begin(), spec.controllers.end(),
                                       [&](const control::ControllerSpec& s) { return s.name == c.name; });
    const std::size_t asked =
        compared == spec.controllers.end() ? 0 : static_cast<std::size_t>(spec.generations_for(*compared));
    for (const auto& f : c.finished) {
      // A run its optimizer stopped early is finished however many generations are asked.
      if (f.generations.size() >= asked || !f.stopped.empty()) {
        p.finished.push_back({c.name, f});
        continue;
      }
      eval::RunState s;
      s.run = f.run;
      s.seed = f.seed;
      s.generations = f.generations;
      s.has_best = true;
      s.best_fitness = f.best_fitness;
      s.best_genome = f.best_genome;
      s.best_generation = f.best_generation;
      s.best_index = f.best_index;
      s.transfer = f.transfer;
      s.success_evaluation = f.success_evaluation;
      std::optional<eval::OptimizerState> kept = find_state(c, f.run);
      if (!kept)
        throw StoreError(fmt::format("run {} of {} in {} finished without keeping the state to carry it on from "
                                     "(it was written by an esc older than schema 4)",
                                     f.run + 1, c.name, file_.string()));
      s.optimizer = std::move(*kept);
      p.in_progress.push_back({c.name, std::move(s)});
    }
    for (const auto& s : c.in_progress) p.in_progress.push_back({c.name, s});
  }
  return p;
}

}  // namespace esc::store
