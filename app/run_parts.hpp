#pragma once
// What starting a run and resuming one do alike (run.cpp, resume.cpp): the overrides on an
// experiment or on every condition of a study, and running a study's conditions.
#include <filesystem>
#include <optional>
#include <vector>

#include "app/campaign_run.hpp"
#include "app/events.hpp"
#include "app/run.hpp"
#include "app/settings.hpp"
#include "runtime/eval/study.hpp"
#include "runtime/store/study_directory.hpp"

namespace esc::app {

// The overrides' settings and controllers on `spec`, which must then fit in memory
// (`where`: `condition `x`: `). Throws Error.
void apply_to_experiment(const Overrides& o, eval::ExperimentSpec& spec, std::string_view where = {});

// Refuses overrides that would make two conditions alike in a resolved setting they differ in
// (one value for every condition would flatten the study), and those of a key the study gives
// to an experiment its conditions depend on; then applies them to every condition. Throws
// Error with every problem.
void apply_to_study(const Overrides& o, eval::StudySpec& study);
// The same without the refusal: the overrides a study was started with, on resume.
void apply_to_conditions(const Overrides& o, eval::StudySpec& study);

// What a stopped study left, per condition; nothing for a new study.
struct StoredStudy {
  const std::vector<eval::ResumePoint>* points = nullptr;   // read from a copy of the database
  const std::vector<store::StoredExperiment>* conditions = nullptr;
  // The generations a carry-on takes each condition to, if any (recorded in the directory
  // before the first runs on: StudyDirectory::carry_on).
  const std::vector<std::optional<int>>* carry_on = nullptr;
};

// Runs every condition not finished yet (into `dir` on rank 0) and returns them all.
[[nodiscard]] std::vector<ConditionOutcome> run_conditions(const eval::StudySpec& study, const Execution& x,
                                                           std::optional<store::StudyDirectory>& dir,
                                                           const StoredStudy& stored, Events& events);

// Tells `events` a note (on rank 0 of an MPI job: the others have nothing to say).
void tell(Events& events, Note note);
void tell(Events& events, Note::Kind kind, std::string text, const std::filesystem::path& dir = {});

// `esc run` of `target` in `script` with the overrides `o`, into `dir`: the command that
// starts a run again.
[[nodiscard]] std::string start_command(const std::filesystem::path& script, const std::string& target,
                                        const Overrides& o, const std::filesystem::path& dir);

// The names, comma-separated.
[[nodiscard]] std::string names_of(const std::vector<std::string>& names);

}  // namespace esc::app
