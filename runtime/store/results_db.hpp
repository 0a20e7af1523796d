#pragma once
// The results database of a run directory: DIR/esc.db, one SQLite file (schema in
// docs/results-store.md). It is the source of truth: every generation is committed in one
// transaction (statistics, the run's best so far and the parents needed to continue), so
// after a crash at any moment the database holds a consistent state to resume from. The
// CSV and JSON files of the directory are views of it, rewritten on resume.
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "runtime/eval/campaign.hpp"
#include "runtime/eval/study.hpp"
#include "runtime/store/directory_lock.hpp"
#include "runtime/store/member_tables.hpp"
#include "runtime/store/sqlite.hpp"
#include "runtime/store/write_ahead_log.hpp"

namespace esc::store {

class DatabaseSnapshot;

inline constexpr const char* kDatabaseFile = "esc.db";
// Beside the database of a run that uses evolved controllers: the runs of the experiments
// it depends on (its dependency cache, written first).
inline constexpr const char* kDependencyCache = "deps";
// 2: GP (table tree_state; runs.best_tree and runs.best_behavior hold a tree controller's
// best tree as script code). 3: studies (tables studies, conditions, condition_settings: a
// study's database holds one experiment row per condition). 4: the analyses' tables
// (analysis_tables.hpp: behavior usage per generation, choices, transfers), and a finished
// run keeps its state. An older database opened for writing is upgraded.
// 5: a checksum on every row (row_checksum.hpp). 6: every optimizer's state in one table,
// and its metrics per generation (optimizer_tables.hpp). 7: the algorithm that evolves each
// controller (controllers.algorithm), and why a run's search ended early (runs.stopped).
// 8: the evaluation of a run that first met the experiment's success test
// (runs.success_evaluation), and what an optimizer keeps beside the best, per generation
// (member_tables.hpp). 9: the optimizer's metrics in their generation's row, their names
// once per controller (metric_tables.hpp). 10: a generation's members in one row
// (member_tables.hpp).
inline constexpr int kSchemaVersion = 10;
// PRAGMA application_id of an esc database: "ESC1".
inline constexpr std::int32_t kApplicationId = 0x45534331;

// A problem with a stored directory (missing, foreign, damaged, mismatched), with a
// message meant for the user.
class StoreError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A directory whose esc.db holds no committed generation: an empty file, a database stopped
// before its experiment was stored, or one stopped before the first generation committed.
// Nothing in it can be resumed or lost; `esc run --out` may reuse it.
class NothingStored : public StoreError {
 public:
  using StoreError::StoreError;
  // What the stopped run was started with, where its database holds that much (it stopped
  // before its first generation): the command that starts it again repeats it.
  struct Launch {
    std::filesystem::path script;
    std::string target;                 // the experiment, or the study
    nlohmann::ordered_json overrides;   // as LaunchInfo stores them
  };
  NothingStored(const std::string& message, std::optional<Launch> launch)
      : StoreError(message), launch_(std::move(launch)) {}
  [[nodiscard]] const std::optional<Launch>& launch() const noexcept { return launch_; }

 private:
  std::optional<Launch> launch_;
};

struct SourceFile {
  std::filesystem::path name;   // as the compiler reported it
  std::string text;
};

// How the campaign was started, kept so that `esc run --resume` can rebuild it.
struct LaunchInfo {
  std::filesystem::path script;                   // absolute path of the script run
  nlohmann::ordered_json overrides = nlohmann::ordered_json::object();   // command-line settings
  std::string software_version;
};

// The fixed columns of a stored replay trace, the first of each row (the rest:
// trace_rows.hpp, trace_columns), and the running fitness's name among them.
inline constexpr std::size_t kTraceColumns = 20;
inline constexpr const char* kRunningFitness = "running_fitness";

struct StoredReplay {
  int run = 0;
  std::uint64_t seed = 0;       // the evaluation's seed
  double fitness = 0.0;
  std::vector<eval::TraceStep> steps;
  // Each epoch's last step counts the epoch's end terms (and the last one the evaluation's),
  // as eval::TraceStep::fitness does now; an esc before that stored the running fitness
  // without them (its column is named `fitness`, not kRunningFitness).
  bool end_terms_counted = true;
};

struct StoredController {
  std::int64_t id = 0;
  std::string name;
  std::string architecture;
  std::size_t genome_size = 0;
  std::string head;                       // "classical", "symbolic", "supervisor" or "tree"
  std::vector<std::string> actions;       // what usage counts: action or behavior names
  std::vector<control::Choice> choices;   // the same, with library and mark (schema 3; else empty)
  // What evolved it: an algorithm's name (evo::Algorithm), or `evaluate` for a controller
  // only evaluated; for a database older than schema 7, `gp` for a tree and `es` otherwise.
  std::string algorithm;
  std::vector<eval::RunResult> finished;  // in run order
  std::vector<eval::RunState> in_progress;
  std::optional<StoredReplay> replay;     // the best run's best evaluation, if traced
  // What its optimizer kept beside the best, per run and generation (schema 8); none for an
  // optimizer that keeps nothing.
  std::optional<StoredMembers> members;
};

// The condition of a study an experiment row is (a study's database holds one per
// condition).
struct StoredCondition {
  std::string study;
  std::uint64_t study_seed = 0;
  int index = 0;                          // in the study's order
  std::string name;
  std::string directory;                  // its files, under the run directory
  std::optional<int> sweep;
  std::vector<eval::ConditionSetting> settings;
};

struct StoredExperiment {
  std::int64_t id = 0;
  std::string name;
  std::uint64_t seed = 0;
  std::string content_hash;
  std::string status;                     // "running" or "finished"
  std::string created;                    // ISO 8601, UTC
  std::string software_version;
  std::filesystem::path script;
  nlohmann::ordered_json overrides;
  std::map<std::string, std::string> settings;
  nlohmann::ordered_json arena;           // walls and obstacles, metres
  double robot_radius_m = 0.0;
  int runs = 0;
  int generations = 0;
  int epochs = 0;
  int steps = 0;
  std::vector<SourceFile> sources;
  std::vector<StoredController> controllers;
  std::optional<StoredCondition> condition;   // a study's condition (schema 3)

  [[nodiscard]] bool finished() const noexcept { return status == "finished"; }
  // The finished runs as a campaign result (what summary.json shows).
  [[nodiscard]] eval::CampaignResult result() const;
};

// The experiments of one run directory (a study's: every condition), as `esc export` and
// `esc report` read them.
struct StoredDirectory {
  std::filesystem::path path;   // as the user named it
  std::vector<StoredExperiment> experiments;
};

// Content key of a campaign: the experiment name and every source file (file name without
// its directory, and text), as 16 hex digits of FNV-1a.
[[nodiscard]] std::string campaign_hash(std::string_view experiment, const std::vector<SourceFile>& sources);

class ResultsDb {
 public:
  // Creates DIR/esc.db and stores the experiment, its sources and settings in one
  // transaction. Throws StoreError if the database exists.
  static ResultsDb create(const std::filesystem::path& dir, const eval::ExperimentSpec& spec,
                          const std::vector<SourceFile>& sources, const LaunchInfo& launch);
  // Creates DIR/esc.db for a study: the study, and for each condition its experiment (as
  // `create` stores one, launched as `launches[i]` says) and what makes it a condition
  // (name, directory, settings), in one transaction. Writes to the first condition.
  static ResultsDb create_study(const std::filesystem::path& dir, const eval::StudySpec& study,
                                const std::vector<SourceFile>& sources, const std::vector<LaunchInfo>& launches);
  // Opens an existing database and checks it is an esc database this version can read,
  // undamaged. Throws StoreError with a clear message otherwise.
  static ResultsDb open(const std::filesystem::path& dir, bool read_only = false);

  // Writes to experiment `id` (a study's condition) from now on.
  void select_experiment(std::int64_t id);

  // One generation of one run, in one transaction: its statistics, the run's best so far
  // and the state to continue from.
  void commit_generation(const std::string& controller, const eval::RunState& state);
  // The run's best evaluation replayed; kept if it is the controller's best run so far.
  void commit_replay(const std::string& controller, const eval::RunResult& run,
                     std::span<const eval::TraceStep> trace);
  // The run is finished: its best genome, behavior usage; its resume state is dropped.
  void commit_run(const std::string& controller, const eval::RunResult& run);
  void mark_finished();
  // An experiment carried on: to `spec`'s generations, started with `overrides` on the
  // command line.
  struct Extension {
    std::int64_t experiment_id = 0;
    const eval::ExperimentSpec* spec = nullptr;
    nlohmann::ordered_json overrides;
  };
  // Each experiment of `extensions` now runs for its spec's generations: its generations,
  // settings and overrides updated and its status `running`, all in one transaction (a
  // study's conditions together, before the first of them runs on).
  void extend(const std::vector<Extension>& extensions);

  // Everything stored, experiment by experiment. Throws StoreError on inconsistent content.
  [[nodiscard]] std::vector<StoredExperiment> load();
  // The experiment this database was created for by `esc run EXPERIMENT` (not a study).
  [[nodiscard]] StoredExperiment load_single();

  // Where `esc run --resume` picks `stored` up, for the generations `spec` asks of each
  // controller: its runs in progress, and the finished runs that have fewer generations,
  // carried on from the state they kept. Throws StoreError when such a run kept none.
  [[nodiscard]] eval::ResumePoint resume_point(const StoredExperiment& stored, const eval::ExperimentSpec& spec);

  // What run `run` of `c` continues from, or (a finished run keeps it) ended with: its
  // optimizer's state (table optimizer_state; for a run an esc before schema 6 left, its ES
  // parents or GP population converted). Throws StoreError when there is none or the stored
  // state is damaged.
  [[nodiscard]] eval::OptimizerState load_state(const StoredController& c, int run);
  // The same, nullopt when there is none (damage still throws).
  [[nodiscard]] std::optional<eval::OptimizerState> find_state(const StoredController& c, int run);

  [[nodiscard]] std::int64_t experiment_id() const noexcept { return experiment_id_; }
  // Where the database's log was damaged when it was opened (write_ahead_log.hpp): what
  // SQLite dropped, past the commit this reads. Opened for writing, those frames are gone.
  [[nodiscard]] const std::optional<LogScan>& log_damage() const noexcept { return log_damage_; }

 private:
  ResultsDb(sql::Database db, std::filesystem::path file);
  // The schema and its facts, no experiment yet.
  static ResultsDb create_empty(const std::filesystem::path& dir, const LaunchInfo& launch);
  // The experiment, its sources, settings and controllers (inside the caller's transaction);
  // selects it and returns its id.
  std::int64_t insert_experiment(const eval::ExperimentSpec& spec, const std::vector<SourceFile>& sources,
                                 const LaunchInfo& launch);
  // The study condition `e` is, if any.
  void load_condition(StoredExperiment& e);
  std::int64_t controller_id(const std::string& name);
  // What evolved `c` in a database older than schema 7, which does not say.
  std::string algorithm_before_7(const StoredController& c);
  void upgrade();   // to kSchemaVersion
  bool column_exists(const std::string& table, const std::string& column);

  std::shared_ptr<const DirectoryLock> lock_;   // written to: no other process writes beside it
  // Read: the copy it reads (database_snapshot.hpp), removed after the database is closed.
  std::shared_ptr<const DatabaseSnapshot> snapshot_;
  int schema_version_ = kSchemaVersion;
  bool has_saturated_ = true;   // generations.saturated (databases before schema 5 lack it)
  std::optional<LogScan> log_damage_;

  sql::Database db_;
  std::filesystem::path file_;
  std::int64_t experiment_id_ = 0;
  std::map<std::string, std::int64_t> controller_ids_;
};

}  // namespace esc::store
