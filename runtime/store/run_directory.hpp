#pragma once
// The output directory of `esc run`. It is written as the campaign goes, so a run that is
// stopped halfway keeps every finished generation:
//   esc.db                     the results database (results_db.hpp), committed every
//                              generation: the source of truth, enough to resume
//   sources/<file>             every script file the experiment was compiled from
//   settings.json              experiment, master seed, resolved settings, content hash
//   <controller>/run-NN.csv    per-generation statistics, one line appended per generation
//   <controller>/run-NN.best.json   best genome of the run and its fitness (a tree
//                              controller's also holds the tree as script code, "tree")
//   <controller>/run-NN.best.esc    tree controllers: the best tree as script code (a
//                              Wheels tree as a behavior declaration, to paste)
//   summary.json               all runs finished so far (rewritten atomically after each)
//   deps/                      the runs of the experiments whose evolved controllers it
//                              uses (kDependencyCache), written before esc.db
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "runtime/eval/campaign.hpp"
#include "runtime/store/results_db.hpp"

namespace esc::store {

class RunDirectory final : public eval::CampaignListener {
 public:
  // Receives the runs finished so far after each one, instead of DIR/summary.json (a
  // study's condition: the study writes one summary of all its conditions).
  using SummarySink = std::function<void(const eval::CampaignResult&)>;

  // Creates `dir` and its database. Throws std::runtime_error if it exists and holds
  // anything but a `deps/` directory (results are never overwritten) or cannot be created.
  RunDirectory(std::filesystem::path dir, const eval::ExperimentSpec& spec,
               const std::vector<SourceFile>& sources, const LaunchInfo& launch = {});

  // Continues a directory whose database was opened and loaded (`stored`), from `point`
  // (ResultsDb::resume_point: finished runs carried on to more generations are in progress
  // there): rewrites the CSV, genome and summary files from the database, which is what
  // survived a crash. A study's condition is opened so too (its results under `dir`, its
  // database the study's, with its experiment selected), with `summary` receiving what
  // summary.json would hold.
  static RunDirectory resume(std::filesystem::path dir, ResultsDb db, const StoredExperiment& stored,
                             const eval::ResumePoint& point, SummarySink summary = {});

  // Before resume(), when the run is carried on to `spec`'s generations: records them in the
  // database (ResultsDb::extend, with the command-line settings `overrides`) and in
  // settings.json.
  static void carry_on(const std::filesystem::path& dir, ResultsDb& db, const eval::ExperimentSpec& spec,
                       const nlohmann::ordered_json& overrides);
  // The resolved settings of `spec` into DIR/settings.json, a view of the database (a file
  // that does not read as JSON stays as it is).
  static void rewrite_settings(const std::filesystem::path& dir, const eval::ExperimentSpec& spec);

  void generation_done(const control::ControllerSpec& controller, int run,
                       const eval::GenerationStats& stats) override;
  void checkpoint(const control::ControllerSpec& controller, const eval::RunState& state) override;
  void best_traced(const control::ControllerSpec& controller, const eval::RunResult& run,
                   std::span<const eval::TraceStep> trace) override;
  void run_done(const control::ControllerSpec& controller, const eval::RunResult& run) override;

  // Final summary (the same file, with every run); marks the campaign finished.
  void finish(const eval::CampaignResult& result);

  [[nodiscard]] const std::filesystem::path& path() const noexcept { return dir_; }

 private:
  RunDirectory(std::filesystem::path dir, ResultsDb db);
  explicit RunDirectory(std::pair<std::filesystem::path, ResultsDb> created);
  std::filesystem::path run_file(const std::string& controller, int run, std::string_view ext) const;
  void write_best(const std::string& controller, const std::string& architecture, const eval::RunResult& run);
  void write_summary();

  std::filesystem::path dir_;
  ResultsDb db_;
  eval::CampaignResult partial_;      // runs finished so far, for summary.json
  // Every compared controller in the experiment's order, with its genome size as tables
  // show it: summary.json lists controllers in this order whichever finishes a run first.
  std::vector<std::pair<std::string, std::size_t>> controllers_;
  std::ofstream csv_;                 // the run being written
  std::string csv_key_;
  SummarySink summary_;               // empty: DIR/summary.json
};

// Makes `dir` for a new run: it must not exist, hold only `deps/` (and an empty `sources/`),
// or hold a run that committed no generation (holds_nothing_stored) and nothing but what
// such a run writes (first_kept_file), whose files it removes (results are never
// overwritten). Throws std::runtime_error otherwise.
[[nodiscard]] std::shared_ptr<const DirectoryLock> create_output_directory(const std::filesystem::path& dir);

// Writes every source file to DIR/sources/NN-<file> (making sources/, after the database);
// returns the list settings.json shows.
[[nodiscard]] nlohmann::ordered_json write_sources(const std::filesystem::path& dir,
                                                   const std::vector<SourceFile>& sources);

// settings.json of an experiment: its name, master seed, content hash, sources (`files`, as
// write_sources listed them) and resolved settings.
[[nodiscard]] nlohmann::ordered_json settings_json(const eval::ExperimentSpec& spec,
                                                   const std::vector<SourceFile>& sources,
                                                   const nlohmann::ordered_json& files);

// The text of a tree controller's run-NN.best.esc: comments saying where the tree comes
// from, then the tree as `behavior CONTROLLER_runNN() { wheels(...) }` to paste (a Wheels
// tree, or an Action tree with its actions inlined); a Behavior tree as a comment.
[[nodiscard]] std::string best_tree_script(const std::string& controller, const std::string& architecture,
                                           const eval::RunResult& run);

// The CSV text of a run's per-generation statistics (header included).
[[nodiscard]] std::string generations_csv(const std::vector<eval::GenerationStats>& generations);

// 64-bit FNV-1a of the text: a stable content key (not a cryptographic hash).
[[nodiscard]] std::uint64_t content_hash(std::string_view text, std::uint64_t h = 0xcbf29ce484222325ULL) noexcept;

// The checksum a genome file (CONTROLLER/run-NN.best.json) carries, 16 hex digits: FNV-1a of
// what a replay uses from it (the controller's name and the run, the genes' and the
// fitness's bit patterns, the evaluation seed, the tree; numbers little-endian, texts after
// their lengths), so a flipped bit in any of them is refused instead of replayed.
[[nodiscard]] std::string genome_checksum(std::string_view controller, int run, const std::vector<double>& genome,
                                          double fitness, std::uint64_t evaluation_seed, std::string_view tree);

// Writes `text` to `file` through a temporary file and a rename, so readers never see a
// half-written file.
void write_atomically(const std::filesystem::path& file, std::string_view text);

}  // namespace esc::store
