#include "runtime/store/results_db.hpp"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <variant>

#include <fmt/format.h>

#include "runtime/store/analysis_tables.hpp"
#include "runtime/store/database_snapshot.hpp"
#include "runtime/store/member_tables.hpp"
#include "runtime/store/metric_tables.hpp"
#include "runtime/store/optimizer_tables.hpp"
#include "runtime/store/page_check.hpp"
#include "runtime/store/results_schema.hpp"
#include "runtime/store/row_checksum.hpp"
#include "runtime/store/run_directory.hpp"
#include "runtime/store/trace_rows.hpp"
#include "runtime/store/unstored_files.hpp"
#include "runtime/store/write_ahead_log.hpp"

namespace esc::store {

namespace fs = std::filesystem;

namespace {

std::string now_utc() {
  const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

// What evolves `c` in `spec`, as the controllers table keeps it.
std::string algorithm_name(const eval::ExperimentSpec& spec, const control::ControllerSpec& c) {
  if (spec.evaluates_only()) return std::string(evo::kEvaluateOnly);
  const evo::Algorithm* a = spec.evolution_of(c).algorithm;
  return a != nullptr ? std::string(a->name) : std::string();
}

nlohmann::ordered_json arena_json(const sim::ArenaSpec& a) {
  nlohmann::ordered_json boxes = nlohmann::ordered_json::array();
  for (const auto& b : a.boxes)
    boxes.push_back({{"x", b.center_m.x}, {"y", b.center_m.y}, {"width", b.size_m.x}, {"height", b.size_m.y},
                     {"angle", b.angle_rad}});
  nlohmann::ordered_json cylinders = nlohmann::ordered_json::array();
  for (const auto& c : a.cylinders)
    cylinders.push_back({{"x", c.center_m.x}, {"y", c.center_m.y}, {"radius", c.radius_m}});
  nlohmann::ordered_json lights = nlohmann::ordered_json::array();
  for (const auto& l : a.lights)
    lights.push_back({{"x", l.position_m.x}, {"y", l.position_m.y}, {"above_zone", l.above_zone}});
  nlohmann::ordered_json zones = nlohmann::ordered_json::array();
  for (const auto& z : a.zones)
    zones.push_back({{"shape", z.shape == sim::ZoneShape::Circle ? "circle" : "rectangle"}, {"x", z.center_m.x},
                     {"y", z.center_m.y}, {"radius", z.radius_m}, {"width", z.size_m.x}, {"height", z.size_m.y},
                     {"visible", z.visible}, {"random_position", z.random_position}, {"recharge", z.recharge}});
  nlohmann::ordered_json out = {{"width", a.width_m}, {"height", a.height_m}, {"boxes", boxes},
                                 {"cylinders", cylinders}, {"lights", lights}, {"zones", zones}};
  // Only in arenas that have them: the others are stored as before they existed.
  if (!a.walls.empty()) {
    nlohmann::ordered_json walls = nlohmann::ordered_json::array();
    for (const auto& w : a.walls)
      walls.push_back({{"x1", w.from_m.x}, {"y1", w.from_m.y}, {"x2", w.to_m.x}, {"y2", w.to_m.y},
                       {"thickness", w.thickness_m}});
    out["walls"] = walls;
  }
  if (a.goal) out["goal"] = {{"x", a.goal->x}, {"y", a.goal->y}};
  return out;
}

}  // namespace

std::string campaign_hash(std::string_view experiment, const std::vector<SourceFile>& sources) {
  // File names without their directories, in name order: the same script run as `a.esc` or
  // as `/x/a.esc` (as `esc run --resume` does, from the stored absolute path) is the same
  // campaign, whatever order the compiler listed its files in.
  std::vector<std::pair<std::string, std::string_view>> files;
  for (const SourceFile& s : sources) files.emplace_back(s.name.filename().generic_string(), s.text);
  std::sort(files.begin(), files.end());
  std::uint64_t h = content_hash(experiment);
  for (const auto& [name, text] : files) h = content_hash(text, content_hash(name, h));
  return fmt::format("{:016x}", h);
}

ResultsDb::ResultsDb(sql::Database db, fs::path file) : db_(std::move(db)), file_(std::move(file)) {}

ResultsDb ResultsDb::create_empty(const fs::path& dir, const LaunchInfo& launch) {
  const fs::path file = dir / kDatabaseFile;
  auto lock = DirectoryLock::acquire(dir);
  if (fs::exists(file)) throw StoreError(fmt::format("{} already exists; results are never overwritten", file.string()));
  ResultsDb r(sql::Database(file, sql::Database::Mode::Create), file);
  r.lock_ = std::move(lock);
  sql::Database& db = r.db_;
  // WAL: a commit is one append to the log, atomic after a crash; synchronous=FULL makes it
  // durable across power loss too (one fsync per generation costs nothing here).
  db.exec("PRAGMA journal_mode=WAL; PRAGMA synchronous=FULL; PRAGMA foreign_keys=ON;");
  sql::Transaction tx(db);
  // The marks of an esc database commit with its tables: a run killed at any instant leaves
  // either a database without tables (nothing stored) or one with every table, never an
  // esc database that lacks them.
  db.exec(fmt::format("PRAGMA application_id={}; PRAGMA user_version={};", kApplicationId, kSchemaVersion));
  db.exec(results_schema());
  db.exec(analysis_schema());
  db.exec(member_schema());
  db.exec(metric_schema());
  auto meta = db.prepare("INSERT INTO meta(key, value) VALUES (?, ?)");
  meta.bind(1, "format").bind(2, "esc results").run();
  meta.bind(1, "schema_version").bind(2, std::to_string(kSchemaVersion)).run();
  meta.bind(1, "software_version").bind(2, launch.software_version).run();
  tx.commit();
  return r;
}

std::int64_t ResultsDb::insert_experiment(const eval::ExperimentSpec& spec, const std::vector<SourceFile>& sources,
                                          const LaunchInfo& launch) {
  sql::Database& db = db_;
  auto ins = db.prepare(
      "INSERT INTO experiments(name, seed, content_hash, status, created, software_version, script_path, "
      "overrides, arena, robot_radius_m, runs, generations, epochs, steps) "
      "VALUES (?, ?, ?, 'running', ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
  ins.bind(1, spec.name)
      .bind(2, std::to_string(spec.seed))
      .bind(3, campaign_hash(spec.name, sources))
      .bind(4, now_utc())
      .bind(5, launch.software_version)
      .bind(6, launch.script.generic_string())
      .bind(7, launch.overrides.dump())
      .bind(8, arena_json(spec.arena).dump())
      .bind(9, spec.robot.body_radius_m)
      .bind(10, spec.runs)
      .bind(11, spec.max_generations())
      .bind(12, spec.epochs)
      .bind(13, spec.steps)
      .run();
  experiment_id_ = db.last_insert_rowid();
  seal_row(db, "experiments", experiment_id_);
  controller_ids_.clear();

  auto src = db.prepare("INSERT INTO sources(experiment_id, idx, name, text) VALUES (?, ?, ?, ?)");
  for (std::size_t i = 0; i < sources.size(); ++i) {
    src.bind(1, experiment_id_).bind(2, static_cast<std::int64_t>(i)).bind(3, sources[i].name.generic_string())
        .bind(4, sources[i].text).run();
    seal_row(db, "sources", db.last_insert_rowid());
  }
  auto set = db.prepare("INSERT INTO settings(experiment_id, key, value) VALUES (?, ?, ?)");
  for (const auto& [k, v] : spec.resolved_settings) {
    set.bind(1, experiment_id_).bind(2, k).bind(3, v).run();
    seal_row(db, "settings", db.last_insert_rowid());
  }
  auto ctl = db.prepare(
      "INSERT INTO controllers(experiment_id, idx, name, architecture, genome_size, head, actions, algorithm) "
      "VALUES (?, ?, ?, ?, ?, ?, ?, ?)");
  for (std::size_t i = 0; i < spec.controllers.size(); ++i) {
    const control::ControllerSpec& c = spec.controllers[i];
    const nlohmann::json actions = c.choice_names();
    ctl.bind(1, experiment_id_).bind(2, static_cast<std::int64_t>(i)).bind(3, c.name).bind(4, c.architecture())
        .bind(5, static_cast<std::int64_t>(spec.genome_size_of(c)))
        .bind(6, c.head_name())
        .bind(7, actions.dump())
        .bind(8, algorithm_name(spec, c))
        .run();
    controller_ids_[c.name] = db.last_insert_rowid();
    seal_row(db, "controllers", controller_ids_[c.name]);
    save_choices(db, controller_ids_[c.name], c.choices);
  }
  return experiment_id_;
}

ResultsDb ResultsDb::create(const fs::path& dir, const eval::ExperimentSpec& spec,
                            const std::vector<SourceFile>& sources, const LaunchInfo& launch) {
  ResultsDb r = create_empty(dir, launch);
  sql::Transaction tx(r.db_);
  (void)r.insert_experiment(spec, sources, launch);
  tx.commit();
  return r;
}

ResultsDb ResultsDb::create_study(const fs::path& dir, const eval::StudySpec& study,
                                  const std::vector<SourceFile>& sources, const std::vector<LaunchInfo>& launches) {
  if (launches.size() != study.conditions.size())
    throw std::invalid_argument("create_study: one launch per condition");
  ResultsDb r = create_empty(dir, launches.empty() ? LaunchInfo{} : launches.front());
  sql::Database& db = r.db_;
  sql::Transaction tx(db);
  db.prepare("INSERT INTO studies(name, seed) VALUES (?, ?)").bind(1, study.name).bind(2, std::to_string(study.seed)).run();
  const std::int64_t study_id = db.last_insert_rowid();
  seal_row(db, "studies", study_id);
  auto cond = db.prepare(
      "INSERT INTO conditions(experiment_id, study_id, idx, name, directory, sweep) VALUES (?, ?, ?, ?, ?, ?)");
  auto set = db.prepare(
      "INSERT INTO condition_settings(experiment_id, idx, key, value, swept, x, x_unit) VALUES (?, ?, ?, ?, ?, ?, ?)");
  for (std::size_t i = 0; i < study.conditions.size(); ++i) {
    const eval::ConditionSpec& c = study.conditions[i];
    const std::int64_t id = r.insert_experiment(c.experiment, sources, launches[i]);
    cond.bind(1, id).bind(2, study_id).bind(3, static_cast<std::int64_t>(i)).bind(4, c.name).bind(5, c.directory);
    if (c.sweep) cond.bind(6, *c.sweep);
    cond.run();
    seal_row(db, "conditions", id);
    for (std::size_t k = 0; k < c.settings.size(); ++k) {
      const eval::ConditionSetting& st = c.settings[k];
      set.bind(1, id).bind(2, static_cast<std::int64_t>(k)).bind(3, st.key).bind(4, st.value).bind(5, st.swept ? 1 : 0)
          .bind(7, st.x_unit);
      if (st.x) set.bind(6, *st.x);
      set.run();
      seal_row(db, "condition_settings", db.last_insert_rowid());
    }
  }
  tx.commit();
  return r;
}

void ResultsDb::select_experiment(std::int64_t id) {
  experiment_id_ = id;
  controller_ids_.clear();
  auto ctl = db_.prepare("SELECT id, name FROM controllers WHERE experiment_id = ?");
  ctl.bind(1, id);
  while (ctl.step()) controller_ids_[ctl.text(1)] = ctl.int64(0);
  if (controller_ids_.empty()) throw StoreError(fmt::format("{} has no experiment {}", file_.string(), id));
}

ResultsDb ResultsDb::open(const fs::path& dir, bool read_only) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw StoreError(fmt::format("`{}` is not a directory", dir.string()));
  const fs::path file = dir / kDatabaseFile;
  const auto nothing = [&] {
    throw_nothing_stored(dir, fmt::format("{} holds no experiment: the run was stopped before it started", file.string()));
  };
  if (!fs::is_regular_file(file, ec)) {
    // What `esc run` writes before its database: the runs of the experiments it depends on.
    if (fs::is_directory(dir / kDependencyCache, ec))
      throw NothingStored(fmt::format("`{}` holds only its dependencies ({}/): the run was stopped before it started",
                                      dir.string(), kDependencyCache));
    throw StoreError(fmt::format("`{}` is not an esc run directory: it has no {}", dir.string(), kDatabaseFile));
  }
  if (fs::file_size(file, ec) == 0 && !ec) {
    // esc.db's first page is written before any frame of its log, and SQLite deletes the log
    // of an empty database: frames beside an empty esc.db are all that is left of it.
    const fs::path log = file.string() + "-wal";
    if (fs::file_size(log, ec) > 32 && !ec)
      throw StoreError(fmt::format("{} is empty but {} holds {} bytes: the database was cut short (damaged), and "
                                   "what its log holds cannot be read without it",
                                   file.string(), log.string(), fs::file_size(log, ec)));
    nothing();
  }
  // Reading needs no lock (export and report read a running run) and reads a snapshot (no
  // file appears beside the database; a read-only directory reads); writing excludes others.
  std::shared_ptr<const DirectoryLock> lock = read_only ? nullptr : DirectoryLock::acquire(dir);
  std::shared_ptr<const DatabaseSnapshot> snapshot = read_only ? std::make_shared<DatabaseSnapshot>(dir) : nullptr;
  const fs::path opened = snapshot ? snapshot->dir() / kDatabaseFile : file;
  // Before SQLite opens it, which may fold the log in or reset it.
  std::optional<LogScan> log_damage = store::log_damage(opened);
  try {
    ResultsDb r(sql::Database(opened, read_only ? sql::Database::Mode::ReadOnly : sql::Database::Mode::ReadWrite),
                file);
    r.lock_ = std::move(lock);
    r.snapshot_ = std::move(snapshot);
    r.log_damage_ = log_damage;
    // Written to from a damaged log's last valid commit on: its valid frames folded into the
    // database and the log emptied first, so that no frame past that commit outlives this.
    if (!read_only && log_damage) r.db_.exec("PRAGMA wal_checkpoint(TRUNCATE);");
    // Stopped while it was being created: no table yet (an esc before this one committed
    // the application id and schema version before the tables).
    // Each statement finished at once: one left pending would lock an upgrade's DROP TABLE.
    const auto single = [&r](const char* query) {
      auto q = r.db_.prepare(query);
      return q.step() ? q.int64(0) : std::int64_t{0};
    };
    if (single("SELECT count(*) FROM sqlite_master") == 0) nothing();
    if (single("PRAGMA application_id") != kApplicationId)
      throw StoreError(fmt::format("{} is an SQLite database but not one written by esc", file.string()));
    const std::int64_t version = single("PRAGMA user_version");
    if (version > kSchemaVersion)
      throw StoreError(fmt::format("{} was written by a newer esc (schema {}; this esc reads up to {})",
                                   file.string(), version, kSchemaVersion));
    if (const std::optional<std::string> problem = page_check_problem(r.db_))
      throw StoreError(fmt::format("{} is damaged: {}", file.string(), *problem));
    if (!read_only) r.db_.exec("PRAGMA synchronous=FULL; PRAGMA foreign_keys=ON;");
    r.schema_version_ = static_cast<int>(version);
    if (!read_only && version < kSchemaVersion) {
      // An upgrade reseals the rows of the tables it adds columns to: they must be as
      // written first (older schemas carry no checksums to check).
      if (version >= 5) verify_rows(r.db_, file);
      r.upgrade();
    }
    r.has_saturated_ = r.column_exists("generations", "saturated");
    auto ex = r.db_.prepare("SELECT id FROM experiments ORDER BY id LIMIT 1");
    if (!ex.step()) nothing();
    r.experiment_id_ = ex.int64(0);
    auto ctl = r.db_.prepare("SELECT id, name FROM controllers WHERE experiment_id = ?");
    ctl.bind(1, r.experiment_id_);
    while (ctl.step()) r.controller_ids_[ctl.text(1)] = ctl.int64(0);
    return r;
  } catch (const NothingStored& e) {
    // Not stopped before it started: what it stored is in frames SQLite dropped.
    if (!log_damage) throw;
    throw NothingStored(fmt::format("{}; its valid part holds no experiment", log_damage_text(file, *log_damage)),
                        e.launch());
  } catch (const sql::SqliteError& e) {
    if (log_damage)   // its tables were in the frames SQLite dropped
      throw StoreError(fmt::format("{}; its valid part is not a readable esc database ({})",
                                   log_damage_text(file, *log_damage), e.what()));
    throw StoreError(fmt::format("{} is damaged or not an esc database: {}", file.string(), e.what()));
  }
}

std::int64_t ResultsDb::controller_id(const std::string& name) {
  const auto it = controller_ids_.find(name);
  if (it == controller_ids_.end()) throw StoreError(fmt::format("the database has no controller `{}`", name));
  return it->second;
}

void ResultsDb::commit_generation(const std::string& controller, const eval::RunState& st) {
  const std::int64_t cid = controller_id(controller);
  const eval::GenerationStats& g = st.generations.back();
  sql::Transaction tx(db_);
  const MetricColumns metrics = metric_columns(db_, cid, g.metrics);
  auto row = db_.prepare(
      "INSERT INTO generations(controller_id, run, generation, best, mean, sd, evaluations, steps, seconds, "
      "saturated, metric_names, metrics) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
  row.bind(1, cid).bind(2, st.run).bind(3, g.generation).bind(4, g.best).bind(5, g.mean).bind(6, g.sd)
      .bind(7, g.evaluations).bind(8, g.steps).bind(9, g.seconds).bind(10, g.saturated);
  if (!metrics.names.empty()) row.bind(11, metrics.names).bind_blob(12, std::span<const double>(metrics.values));
  row.run();
  seal_row(db_, "generations", db_.last_insert_rowid());
  auto run = db_.prepare(
      "INSERT OR REPLACE INTO runs(controller_id, run, seed, status, generations_done, best_fitness, "
      "best_generation, best_index, best_genome, success_evaluation) VALUES (?, ?, ?, 'running', ?, ?, ?, ?, ?, ?)");
  run.bind(1, cid).bind(2, st.run).bind(3, std::to_string(st.seed)).bind(4, static_cast<std::int64_t>(st.generations.size()));
  if (st.has_best)
    run.bind(5, st.best_fitness).bind(6, st.best_generation).bind(7, st.best_index).bind_blob(8, st.best_genome);
  if (st.success_evaluation) run.bind(9, *st.success_evaluation);
  run.run();
  seal_row(db_, "runs", db_.last_insert_rowid());
  save_state(db_, cid, st.run, st.optimizer);
  if (st.member_layout) save_members(db_, cid, st, g.generation);
  save_usage(db_, cid, st.run, g);
  if (st.transfer) save_transfer(db_, cid, st.run, *st.transfer);
  tx.commit();
}

void ResultsDb::commit_replay(const std::string& controller, const eval::RunResult& run,
                              std::span<const eval::TraceStep> trace) {
  const std::int64_t cid = controller_id(controller);
  const std::uint64_t seed = eval::evaluation_seed(run.seed, run.best_generation, static_cast<std::size_t>(run.best_index));
  const nlohmann::json columns = trace_columns(trace);
  sql::Transaction tx(db_);
  // One replay per controller: its best run's (the earliest run on a tie, whichever order
  // the runs finish in). Replaying the same run again (after a resume, or when the run was
  // carried on to more generations) rewrites the same row.
  db_.prepare(
         "INSERT INTO replays(controller_id, run, seed, fitness, columns, trace) VALUES (?, ?, ?, ?, ?, ?) "
         "ON CONFLICT(controller_id) DO UPDATE SET run = excluded.run, seed = excluded.seed, "
         "fitness = excluded.fitness, columns = excluded.columns, trace = excluded.trace "
         "WHERE excluded.fitness > replays.fitness OR excluded.run = replays.run "
         "OR (excluded.fitness = replays.fitness AND excluded.run < replays.run)")
      .bind(1, cid).bind(2, run.run).bind(3, std::to_string(seed)).bind(4, run.best_fitness).bind(5, columns.dump())
      .bind_blob(6, pack_trace(trace))
      .run();
  seal_row(db_, "replays", cid);   // its rowid, whether the row changed or not
  tx.commit();
}

void ResultsDb::commit_run(const std::string& controller, const eval::RunResult& run) {
  const std::int64_t cid = controller_id(controller);
  std::vector<std::string> actions;
  {
    auto q = db_.prepare("SELECT actions FROM controllers WHERE id = ?");
    q.bind(1, cid);
    if (q.step()) actions = nlohmann::json::parse(q.text(0)).get<std::vector<std::string>>();
  }
  sql::Transaction tx(db_);
  auto row = db_.prepare(
      "INSERT OR REPLACE INTO runs(controller_id, run, seed, status, generations_done, best_fitness, "
      "best_generation, best_index, best_genome, best_tree, best_behavior, stopped, success_evaluation) "
      "VALUES (?, ?, ?, 'finished', ?, ?, ?, ?, ?, ?, ?, ?, ?)");
  row.bind(1, cid).bind(2, run.run).bind(3, std::to_string(run.seed))
      .bind(4, static_cast<std::int64_t>(run.generations.size())).bind(5, run.best_fitness)
      .bind(6, run.best_generation).bind(7, run.best_index).bind_blob(8, run.best_genome);
  if (!run.best_tree.empty()) row.bind(9, run.best_tree);
  if (!run.best_behavior.empty()) row.bind(10, run.best_behavior);
  if (!run.stopped.empty()) row.bind(11, run.stopped);
  if (run.success_evaluation) row.bind(12, *run.success_evaluation);
  row.run();
  seal_row(db_, "runs", db_.last_insert_rowid());
  // The run's state (optimizer_state) stays, compressed: `esc run --resume DIR --generations G`
  // carries a finished run on from it.
  compress_state(db_, cid, run.run);
  db_.prepare("DELETE FROM behavior_usage WHERE controller_id = ? AND run = ?").bind(1, cid).bind(2, run.run).run();
  auto use = db_.prepare(
      "INSERT INTO behavior_usage(controller_id, run, action_idx, action, steps) VALUES (?, ?, ?, ?, ?)");
  for (std::size_t i = 0; i < run.action_usage.size(); ++i) {
    use.bind(1, cid).bind(2, run.run).bind(3, static_cast<std::int64_t>(i))
        .bind(4, i < actions.size() ? actions[i] : fmt::format("action{}", i)).bind(5, run.action_usage[i])
        .run();
    seal_row(db_, "behavior_usage", db_.last_insert_rowid());
  }
  tx.commit();
}

void ResultsDb::mark_finished() {
  sql::Transaction tx(db_);
  db_.prepare("UPDATE experiments SET status = 'finished' WHERE id = ?").bind(1, experiment_id_).run();
  seal_row(db_, "experiments", experiment_id_);
  tx.commit();
}

void ResultsDb::extend(const std::vector<Extension>& extensions) {
  sql::Transaction tx(db_);
  auto row = db_.prepare("UPDATE experiments SET generations = ?, overrides = ?, status = 'running' WHERE id = ?");
  auto set = db_.prepare("INSERT OR REPLACE INTO settings(experiment_id, key, value) VALUES (?, ?, ?)");
  for (const Extension& x : extensions) {
    row.bind(1, x.spec->max_generations()).bind(2, x.overrides.dump()).bind(3, x.experiment_id).run();
    seal_row(db_, "experiments", x.experiment_id);
    for (const auto& [k, v] : x.spec->resolved_settings) {
      set.bind(1, x.experiment_id).bind(2, k).bind(3, v).run();
      seal_row(db_, "settings", db_.last_insert_rowid());
    }
  }
  tx.commit();
}

}  // namespace esc::store
