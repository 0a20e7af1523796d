#pragma once
// The output directory of `esc run` for a study: one database and one summary for every
// condition, each condition's files in a directory of its own:
//   esc.db                       the results database: one experiment row per condition,
//                                and the study's tables (results_db.hpp)
//   sources/<file>               every script file the study was compiled from
//   settings.json                the study, its master seed and its conditions
//   summary.json                 every condition's runs finished so far (summary_json.hpp)
//   <condition>/settings.json    the condition's experiment, settings and resolved settings
//   <condition>/<controller>/run-NN.csv, .best.json, .best.esc   as in a run directory
// Conditions run one after another; each is a RunDirectory over the study's database.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "runtime/eval/study.hpp"
#include "runtime/store/results_db.hpp"
#include "runtime/store/run_directory.hpp"
#include "runtime/store/summary_json.hpp"

namespace esc::store {

class StudyDirectory {
 public:
  // Creates `dir` (which must not exist, or hold only `deps/`), its database holding every
  // condition, and its files; `launches`: how each condition was started.
  StudyDirectory(std::filesystem::path dir, const eval::StudySpec& study, const std::vector<SourceFile>& sources,
                 const std::vector<LaunchInfo>& launches);
  // Continues `dir`, whose database holds `stored` (every condition, loaded): rewrites
  // summary.json from it.
  StudyDirectory(std::filesystem::path dir, std::vector<StoredExperiment> stored);
  StudyDirectory(const StudyDirectory&) = delete;
  StudyDirectory& operator=(const StudyDirectory&) = delete;

  // A directory opened for writing: its lock and what its database holds.
  struct Opened {
    std::shared_ptr<const DirectoryLock> lock;
    std::vector<StoredExperiment> stored;
  };

  // A condition carried on to `spec`'s generations, with these command-line settings.
  struct CarryOn {
    const eval::ExperimentSpec* spec;
    nlohmann::ordered_json overrides;
  };
  // Records a carry-on of the conditions (`conditions[i]` for condition i, none where it
  // is not carried on) before the first of them runs on: in the database in one
  // transaction (ResultsDb::extend), then in each one's settings.json. A carry-on stopped
  // in any condition is then finished by a plain resume, every condition to its target.
  void carry_on(const std::vector<std::optional<CarryOn>>& conditions);
  // The listener of condition `i`'s campaign: its files under DIR/<condition>/ (rewritten
  // from the database), its results in its experiment of the database; each finished run
  // rewrites the study's summary.json. The StudyDirectory must outlive it. `point`: where
  // the condition resumes (ResultsDb::resume_point; empty for a new one).
  [[nodiscard]] RunDirectory open_condition(std::size_t i, const eval::ResumePoint& point);
  // What the database held of condition `i` when this directory was opened.
  [[nodiscard]] const StoredExperiment& stored(std::size_t i) const { return stored_.at(i); }
  [[nodiscard]] std::size_t size() const noexcept { return stored_.size(); }
  [[nodiscard]] const std::filesystem::path& path() const noexcept { return dir_; }

 private:
  StudyDirectory(std::filesystem::path dir, Opened opened);
  void write_summary() const;

  std::filesystem::path dir_;
  std::shared_ptr<const DirectoryLock> lock_;   // held while it runs: no other process writes in it
  std::string name_;
  std::uint64_t seed_ = 0;
  std::vector<StoredExperiment> stored_;     // in the study's order
  std::vector<ConditionSummary> summaries_;  // runs finished so far, per condition
};

// The conditions of a study's database, in the study's order; throws StoreError when it
// holds none or something else beside them.
[[nodiscard]] std::vector<StoredExperiment> study_conditions(std::vector<StoredExperiment> all);

}  // namespace esc::store
