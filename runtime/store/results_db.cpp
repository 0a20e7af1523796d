#include "runtime/store/results_db.hpp"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <variant>

#include <fmt/format.h>

#include "runtime/store/analysis_tables.hpp"
#include "runtime/store/database_snapshot.hpp"
#include "runtime/store/es_state.hpp"
#include "runtime/store/member_tables.hpp"
#include "runtime/store/optimizer_tables.hpp"
#include "runtime/store/page_check.hpp"
#include "runtime/store/row_checksum.hpp"
#include "runtime/store/run_directory.hpp"
#include "runtime/store/tree_state.hpp"
#include "runtime/store/unstored_files.hpp"
#include "runtime/store/write_ahead_log.hpp"

namespace esc::store {

namespace fs = std::filesystem;

namespace {

// Every table but meta ends its columns with `checksum` (schema 5, row_checksum.hpp): the
// hash of the row's other columns, written with the row.
constexpr const char* kSchema = R"sql(
CREATE TABLE meta (
  key   TEXT PRIMARY KEY,
  value TEXT NOT NULL
);
CREATE TABLE experiments (
  id               INTEGER PRIMARY KEY,
  name             TEXT NOT NULL,
  seed             TEXT NOT NULL,
  content_hash     TEXT NOT NULL,
  status           TEXT NOT NULL CHECK (status IN ('running', 'finished')),
  created          TEXT NOT NULL,
  software_version TEXT NOT NULL,
  script_path      TEXT NOT NULL,
  overrides        TEXT NOT NULL,
  arena            TEXT NOT NULL,
  robot_radius_m   REAL NOT NULL,
  runs             INTEGER NOT NULL,
  generations      INTEGER NOT NULL,
  epochs           INTEGER NOT NULL,
  steps            INTEGER NOT NULL,
  checksum         INTEGER NOT NULL DEFAULT 0
);
CREATE TABLE sources (
  experiment_id INTEGER NOT NULL REFERENCES experiments(id),
  idx           INTEGER NOT NULL,
  name          TEXT NOT NULL,
  text          TEXT NOT NULL,
  checksum      INTEGER NOT NULL DEFAULT 0,
  PRIMARY KEY (experiment_id, idx)
);
CREATE TABLE settings (
  experiment_id INTEGER NOT NULL REFERENCES experiments(id),
  key           TEXT NOT NULL,
  value         TEXT NOT NULL,
  checksum      INTEGER NOT NULL DEFAULT 0,
  PRIMARY KEY (experiment_id, key)
);
CREATE TABLE controllers (
  id            INTEGER PRIMARY KEY,
  experiment_id INTEGER NOT NULL REFERENCES experiments(id),
  idx           INTEGER NOT NULL,
  name          TEXT NOT NULL,
  architecture  TEXT NOT NULL,
  genome_size   INTEGER NOT NULL,
  head          TEXT NOT NULL,
  actions       TEXT NOT NULL,
  algorithm     TEXT,              -- schema 7; NULL in older rows: `gp` for a tree, else `es`
  checksum      INTEGER NOT NULL DEFAULT 0,
  UNIQUE (experiment_id, name)
);
CREATE TABLE runs (
  controller_id    INTEGER NOT NULL REFERENCES controllers(id),
  run              INTEGER NOT NULL,
  seed             TEXT NOT NULL,
  status           TEXT NOT NULL CHECK (status IN ('running', 'finished')),
  generations_done INTEGER NOT NULL,
  best_fitness     REAL,
  best_generation  INTEGER,
  best_index       INTEGER,
  best_genome      BLOB,
  best_tree        TEXT,
  best_behavior    TEXT,
  stopped          TEXT,             -- schema 7: why the optimizer ended the search early
  -- 8: the run's evaluations up to its first success (`success when`); NULL: none yet
  success_evaluation INTEGER,
  checksum         INTEGER NOT NULL DEFAULT 0,
  PRIMARY KEY (controller_id, run)
);
CREATE TABLE generations (
  controller_id INTEGER NOT NULL REFERENCES controllers(id),
  run           INTEGER NOT NULL,
  generation    INTEGER NOT NULL,
  best          REAL NOT NULL,
  mean          REAL NOT NULL,
  sd            REAL NOT NULL,
  evaluations   INTEGER NOT NULL,
  steps         INTEGER NOT NULL,
  seconds       REAL NOT NULL,
  -- Evaluations whose fitness saturated at +-1e300 (schema 5: an older database gets the
  -- column, 0, when opened for writing and reads as 0 otherwise).
  saturated     INTEGER NOT NULL DEFAULT 0,
  checksum      INTEGER NOT NULL DEFAULT 0,
  PRIMARY KEY (controller_id, run, generation)
);
CREATE TABLE run_state (
  controller_id INTEGER NOT NULL REFERENCES controllers(id),
  run           INTEGER NOT NULL,
  parents       INTEGER NOT NULL,
  genome_size   INTEGER NOT NULL,
  sigma_count   INTEGER NOT NULL,
  population    BLOB NOT NULL,
  checksum      INTEGER NOT NULL DEFAULT 0,
  PRIMARY KEY (controller_id, run)
);
-- Schema 2 (GP); also what opening a schema-1 database for writing adds to it.
CREATE TABLE tree_state (
  controller_id INTEGER NOT NULL REFERENCES controllers(id),
  run           INTEGER NOT NULL,
  individuals   INTEGER NOT NULL,
  population    BLOB NOT NULL,
  checksum      INTEGER NOT NULL DEFAULT 0,
  PRIMARY KEY (controller_id, run)
);
CREATE TABLE behavior_usage (
  controller_id INTEGER NOT NULL REFERENCES controllers(id),
  run           INTEGER NOT NULL,
  action_idx    INTEGER NOT NULL,
  action        TEXT NOT NULL,
  steps         INTEGER NOT NULL,
  checksum      INTEGER NOT NULL DEFAULT 0,
  PRIMARY KEY (controller_id, run, action_idx)
);
CREATE TABLE replays (
  controller_id INTEGER PRIMARY KEY REFERENCES controllers(id),
  run           INTEGER NOT NULL,
  seed          TEXT NOT NULL,
  fitness       REAL NOT NULL,
  columns       TEXT NOT NULL,
  trace         BLOB NOT NULL,
  checksum      INTEGER NOT NULL DEFAULT 0
);
-- Schema 6: every optimizer's state (optimizer_tables.hpp); run_state and tree_state above
-- are read only, for runs an older esc left.
CREATE TABLE optimizer_state (
  controller_id INTEGER NOT NULL REFERENCES controllers(id),
  run           INTEGER NOT NULL,
  algorithm     TEXT NOT NULL,
  format        INTEGER NOT NULL,
  state         BLOB NOT NULL,
  checksum      INTEGER NOT NULL DEFAULT 0,
  PRIMARY KEY (controller_id, run)
);
CREATE TABLE metrics (
  controller_id INTEGER NOT NULL REFERENCES controllers(id),
  run           INTEGER NOT NULL,
  generation    INTEGER NOT NULL,
  idx           INTEGER NOT NULL,
  name          TEXT NOT NULL,
  value         REAL,              -- NULL: NaN
  checksum      INTEGER NOT NULL DEFAULT 0,
  PRIMARY KEY (controller_id, run, generation, idx)
);
-- Schema 3 (studies); also what opening an older database for writing adds to it.
CREATE TABLE studies (
  id            INTEGER PRIMARY KEY,
  name          TEXT NOT NULL,
  seed          TEXT NOT NULL,
  checksum      INTEGER NOT NULL DEFAULT 0
);
CREATE TABLE conditions (
  experiment_id INTEGER PRIMARY KEY REFERENCES experiments(id),
  study_id      INTEGER NOT NULL REFERENCES studies(id),
  idx           INTEGER NOT NULL,
  name          TEXT NOT NULL,
  directory     TEXT NOT NULL,
  sweep         INTEGER,
  checksum      INTEGER NOT NULL DEFAULT 0,
  UNIQUE (study_id, name)
);
CREATE TABLE condition_settings (
  experiment_id INTEGER NOT NULL REFERENCES conditions(experiment_id),
  idx           INTEGER NOT NULL,
  key           TEXT NOT NULL,
  value         TEXT NOT NULL,
  swept         INTEGER NOT NULL,
  x             REAL,
  x_unit        TEXT NOT NULL,
  checksum      INTEGER NOT NULL DEFAULT 0,
  PRIMARY KEY (experiment_id, idx)
);
)sql";

std::string now_utc() {
  const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

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

// A replay row: the kTraceColumns fixed columns, then the accumulator level, the position
// of each of the arena's zones in this epoch (x, y), the light sensors, and the rangefinders
// and goal radars the robot declares. Traces stored before these columns existed have
// exactly kTraceColumns per row, or no light, range or radar columns: the stored column
// names say which, so that a trace is read back as it was written.
struct TraceLayout {
  bool extended = true;   // the accumulator and zones follow the fixed columns
  std::size_t zones = 0;
  bool lights = true;
  std::size_t ranges = 0;
  std::size_t radars = 0;

  [[nodiscard]] std::size_t width() const noexcept {
    if (!extended) return kTraceColumns;
    return kTraceColumns + 1 + 2 * zones + (lights ? static_cast<std::size_t>(sim::kLightSensors) : 0) + ranges +
           radars;
  }
};

TraceLayout layout_of(std::span<const eval::TraceStep> trace) {
  if (trace.empty()) return {};
  const eval::TraceStep& t = trace.front();
  return {true, t.zone_count, true, t.range_count, t.radar_count};
}

std::size_t count_prefixed(const std::vector<std::string>& columns, std::string_view prefix) {
  return static_cast<std::size_t>(std::count_if(columns.begin(), columns.end(), [&](const std::string& c) {
    return c.size() > prefix.size() && c.starts_with(prefix) &&
           std::all_of(c.begin() + static_cast<std::ptrdiff_t>(prefix.size()), c.end(),
                       [](char ch) { return ch >= '0' && ch <= '9'; });
  }));
}

TraceLayout layout_of(const std::vector<std::string>& columns) {
  TraceLayout l;
  l.extended = columns.size() > kTraceColumns;
  l.zones = static_cast<std::size_t>(std::count_if(columns.begin(), columns.end(), [](const std::string& c) {
    return c.starts_with("zone") && c.ends_with("_x");
  }));
  l.lights = count_prefixed(columns, "light") != 0;
  l.ranges = count_prefixed(columns, "range");
  l.radars = count_prefixed(columns, "radar");
  return l;
}

std::vector<double> pack_trace(std::span<const eval::TraceStep> trace) {
  const TraceLayout layout = layout_of(trace);
  std::vector<double> v;
  v.reserve(trace.size() * layout.width());
  for (const auto& t : trace) {
    v.push_back(t.epoch);
    v.push_back(t.step);
    v.push_back(t.pose.x_m);
    v.push_back(t.pose.y_m);
    v.push_back(t.pose.heading_rad);
    v.insert(v.end(), t.ir.begin(), t.ir.end());
    v.push_back(t.left_command);
    v.push_back(t.right_command);
    v.push_back(t.left_speed_mps);
    v.push_back(t.right_speed_mps);
    v.push_back(t.action);
    v.push_back(t.fitness);
    v.push_back(t.collided ? 1.0 : 0.0);
    v.push_back(t.energy);
    for (std::size_t z = 0; z < layout.zones; ++z) {
      v.push_back(t.zones[z].x);
      v.push_back(t.zones[z].y);
    }
    v.insert(v.end(), t.light.begin(), t.light.end());
    v.insert(v.end(), t.range.begin(), t.range.begin() + static_cast<std::ptrdiff_t>(layout.ranges));
    v.insert(v.end(), t.radar.begin(), t.radar.begin() + static_cast<std::ptrdiff_t>(layout.radars));
  }
  return v;
}

std::vector<eval::TraceStep> unpack_trace(const std::vector<double>& v, const std::vector<std::string>& columns) {
  const std::size_t width = columns.size();
  const TraceLayout layout = layout_of(columns);
  if (width < kTraceColumns || layout.width() != width || layout.zones > sim::kMaxZones ||
      layout.ranges > static_cast<std::size_t>(sim::kMaxRangefinders) ||
      layout.radars > static_cast<std::size_t>(sim::kMaxRadars))
    throw StoreError(fmt::format("the database is damaged: a replay trace has {} columns", width));
  if (v.size() % width != 0) throw StoreError("the database is damaged: a replay trace has a partial row");
  std::vector<eval::TraceStep> out(v.size() / width);
  for (std::size_t i = 0; i < out.size(); ++i) {
    const double* r = &v[i * width];
    eval::TraceStep& t = out[i];
    t.epoch = static_cast<int>(r[0]);
    t.step = static_cast<int>(r[1]);
    t.pose = {r[2], r[3], r[4]};
    for (std::size_t k = 0; k < t.ir.size(); ++k) t.ir[k] = r[5 + k];
    t.left_command = r[13];
    t.right_command = r[14];
    t.left_speed_mps = r[15];
    t.right_speed_mps = r[16];
    t.action = static_cast<int>(r[17]);
    t.fitness = r[18];
    t.collided = r[19] != 0.0;
    if (!layout.extended) continue;
    const double* c = r + kTraceColumns;
    t.energy = *c++;
    t.zone_count = layout.zones;
    for (std::size_t z = 0; z < layout.zones; ++z, c += 2) t.zones[z] = {c[0], c[1]};
    if (layout.lights)
      for (double& l : t.light) l = *c++;
    t.range_count = layout.ranges;
    for (std::size_t k = 0; k < layout.ranges; ++k) t.range[k] = *c++;
    t.radar_count = layout.radars;
    for (std::size_t k = 0; k < layout.radars; ++k) t.radar[k] = *c++;
  }
  return out;
}

}  // namespace

std::vector<std::string> trace_column_names(std::size_t zones, std::size_t ranges, std::size_t radars) {
  std::vector<std::string> c = {"epoch", "step", "x", "y", "heading"};
  for (int i = 0; i < sim::kIrSensors; ++i) c.push_back(fmt::format("ir{}", i));
  for (const char* n : {"left_command", "right_command", "left_speed", "right_speed", "action", kRunningFitness,
                        "collided"})
    c.emplace_back(n);
  c.emplace_back("energy");
  for (std::size_t z = 0; z < zones; ++z) {
    c.push_back(fmt::format("zone{}_x", z));
    c.push_back(fmt::format("zone{}_y", z));
  }
  for (int i = 0; i < sim::kLightSensors; ++i) c.push_back(fmt::format("light{}", i));
  for (std::size_t i = 0; i < ranges; ++i) c.push_back(fmt::format("range{}", i));
  for (std::size_t i = 0; i < radars; ++i) c.push_back(fmt::format("radar{}", i));
  return c;
}

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
  db.exec(kSchema);
  db.exec(analysis_schema());
  db.exec(member_schema());
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
    auto tables = r.db_.prepare("SELECT count(*) FROM sqlite_master");
    if (tables.step() && tables.int64(0) == 0) nothing();
    auto id = r.db_.prepare("PRAGMA application_id");
    const std::int64_t app = id.step() ? id.int64(0) : 0;
    if (app != kApplicationId)
      throw StoreError(fmt::format("{} is an SQLite database but not one written by esc", file.string()));
    auto ver = r.db_.prepare("PRAGMA user_version");
    const std::int64_t version = ver.step() ? ver.int64(0) : 0;
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

bool ResultsDb::column_exists(const std::string& table, const std::string& column) {
  auto info = db_.prepare(fmt::format("PRAGMA table_info({})", table));
  while (info.step())
    if (info.text(1) == column) return true;
  return false;
}

void ResultsDb::upgrade() {
  // Each step adds what its version needs; what is stored is untouched.
  sql::Transaction tx(db_);
  const std::string schema = kSchema;
  const auto tables = [&](const char* first, const char* end) {
    const std::size_t a = schema.find(first);
    db_.exec(schema.substr(a, end == nullptr ? std::string::npos : schema.find(end) - a));
  };
  if (schema_version_ < 2) {   // GP
    db_.exec("ALTER TABLE runs ADD COLUMN best_behavior TEXT;");
    tables("CREATE TABLE tree_state", "CREATE TABLE behavior_usage");
  }
  if (schema_version_ < 3) tables("CREATE TABLE studies", nullptr);   // studies
  // The analyses' tables, empty: the generations stored before have no usage.
  if (schema_version_ < kAnalysisSchemaVersion) db_.exec(analysis_schema());
  if (schema_version_ < 6) tables("CREATE TABLE optimizer_state", "CREATE TABLE studies");   // optimizers
  if (schema_version_ < 7) {   // each controller's algorithm, a run's early stop
    db_.exec("ALTER TABLE controllers ADD COLUMN algorithm TEXT; ALTER TABLE runs ADD COLUMN stopped TEXT;");
    if (schema_version_ == 6)   // the algorithm that saved each controller's run states
      db_.exec("UPDATE controllers SET algorithm = (SELECT s.algorithm FROM optimizer_state s "
               "WHERE s.controller_id = controllers.id LIMIT 1);");
    // Their rows' checksums covered the columns they had (an older schema's are sealed below).
    if (schema_version_ >= 5) {
      seal_table(db_, "controllers");
      seal_table(db_, "runs");
    }
  }
  if (schema_version_ < kMemberSchemaVersion) {   // 8: a run's first successful evaluation, members
    db_.exec("ALTER TABLE runs ADD COLUMN success_evaluation INTEGER;");
    if (schema_version_ >= 5) seal_table(db_, "runs");   // the rows now hold one more column
    db_.exec(member_schema());
  }
  if (schema_version_ < 5) {   // saturated evaluations, checksums (the analyses' tables too)
    if (!column_exists("generations", "saturated"))
      db_.exec("ALTER TABLE generations ADD COLUMN saturated INTEGER NOT NULL DEFAULT 0;");
    for (const std::string_view t : sealed_tables()) {
      if (!column_exists(std::string(t), "checksum"))
        db_.exec(fmt::format("ALTER TABLE {} ADD COLUMN checksum INTEGER NOT NULL DEFAULT 0;", t));
      seal_table(db_, t);
    }
  }
  db_.exec(fmt::format("PRAGMA user_version={};", kSchemaVersion));
  tx.commit();
  schema_version_ = kSchemaVersion;
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
  db_.prepare(
         "INSERT INTO generations(controller_id, run, generation, best, mean, sd, evaluations, steps, seconds, "
         "saturated) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?)")
      .bind(1, cid).bind(2, st.run).bind(3, g.generation).bind(4, g.best).bind(5, g.mean).bind(6, g.sd)
      .bind(7, g.evaluations).bind(8, g.steps).bind(9, g.seconds).bind(10, g.saturated)
      .run();
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
  save_metrics(db_, cid, st.run, g);
  if (st.member_layout) save_members(db_, cid, st, g.generation);
  save_usage(db_, cid, st.run, g);
  if (st.transfer) save_transfer(db_, cid, st.run, *st.transfer);
  tx.commit();
}

void ResultsDb::commit_replay(const std::string& controller, const eval::RunResult& run,
                              std::span<const eval::TraceStep> trace) {
  const std::int64_t cid = controller_id(controller);
  const std::uint64_t seed = eval::evaluation_seed(run.seed, run.best_generation, static_cast<std::size_t>(run.best_index));
  const eval::TraceStep none;
  const eval::TraceStep& first = trace.empty() ? none : trace.front();
  const nlohmann::json columns = trace_column_names(first.zone_count, first.range_count, first.radar_count);
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
  // The run's state (optimizer_state) stays: `esc run --resume DIR --generations G`
  // carries a finished run on from it.
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
      for (StoredController& c : e.controllers) {
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
              fmt::format("SELECT generation, best, mean, sd, evaluations, steps, seconds, {} FROM generations "
                          "WHERE controller_id = ? AND run = ? ORDER BY generation",
                          has_saturated_ ? "saturated" : "0"));
          g.bind(1, c.id).bind(2, run);
          while (g.step())
            gens.push_back({g.integer(0), g.real(1), g.real(2), g.real(3), g.int64(4), g.int64(5), g.real(6), {}, g.int64(7)});
          const auto done = static_cast<std::size_t>(runs.int64(3));
          bool contiguous = gens.size() == done;
          for (std::size_t i = 0; contiguous && i < gens.size(); ++i) contiguous = gens[i].generation == static_cast<int>(i);
          if (!contiguous)
            throw StoreError(fmt::format("{} is damaged: run {} of {} has {} generations stored, {} expected",
                                         file_.string(), run + 1, c.name, gens.size(), done));
          std::optional<eval::Transfer> transfer;
          const std::string damaged = fmt::format("{} is damaged: run {} of {}", file_.string(), run + 1, c.name);
          if (schema_version_ >= kAnalysisSchemaVersion) {
            load_usage(db_, c.id, run, gens, damaged);
            transfer = load_transfer(db_, c.id, run);
          }
          if (schema_version_ >= 6) load_metrics(db_, c.id, run, gens, damaged);
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
        if (schema_version_ >= kMemberSchemaVersion) c.members = load_members(db_, c.id);
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

eval::OptimizerState ResultsDb::load_state(const StoredController& c, int run) {
  const std::string damaged = fmt::format("{} is damaged: run {} of {}", file_.string(), run + 1, c.name);
  if (schema_version_ >= 6)
    if (auto s = load_optimizer_state(db_, c.id, run)) return std::move(*s);
  if (auto es = load_es_state(db_, c.id, run, c.genome_size, damaged)) return std::move(*es);
  if (schema_version_ >= 2)   // a schema-1 database holds no trees
    if (auto gp = load_tree_state(db_, c.id, run, damaged)) return std::move(*gp);
  throw StoreError(damaged + " is unfinished but has no state to resume from");
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
      try {
        s.optimizer = load_state(c, f.run);
      } catch (const StoreError&) {
        throw StoreError(fmt::format("run {} of {} in {} finished without keeping the state to carry it on from "
                                     "(it was written by an esc older than schema 4)",
                                     f.run + 1, c.name, file_.string()));
      }
      p.in_progress.push_back({c.name, std::move(s)});
    }
    for (const auto& s : c.in_progress) p.in_progress.push_back({c.name, s});
  }
  return p;
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
