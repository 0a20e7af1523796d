#pragma once
// The experiment a stored run ran, set up again to evaluate its genomes (`esc replay`,
// re-evaluation from Python): compiled from the sources the run stored, whatever has
// happened to the files since, with the settings it ran with; or an experiment of another
// script, evaluated with the run's choice of controllers. Behaviors it froze from other
// experiments are read from the run's dependency cache, never run.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "app/events.hpp"
#include "compiler/compiler.hpp"
#include "runtime/store/results_db.hpp"

namespace esc::app {

struct StoredRun {
  const store::StoredExperiment* stored = nullptr;   // null: a genome file outside any run
  std::filesystem::path root;                        // the directory holding its esc.db
  std::filesystem::path dir;                         // as named: the root, or a study condition's
};

// The experiment `run` ran, as it ran it (its carried-on generations included); throws Error
// when the stored sources no longer compile to the run's script and settings.
[[nodiscard]] eval::ExperimentSpec experiment_of_run(const StoredRun& run, const compiler::CompileOptions& options,
                                                     Events& events);

// Experiment `experiment` of `script` (its first when empty), with the run's controllers and
// dependency cache but none of its settings.
[[nodiscard]] eval::ExperimentSpec experiment_for_run(const StoredRun& run, const std::filesystem::path& script,
                                                      const std::string& experiment,
                                                      const compiler::CompileOptions& options, Events& events);

// Stored controller `controller` and its finished run `run` (from 0). Throws Error when the
// run has no such controller or that run is not finished.
struct FinishedRun {
  const store::StoredController* controller;
  const eval::RunResult* run;
};
[[nodiscard]] FinishedRun finished_run(const StoredRun& stored, const std::string& controller, int run);

// What run `run` (from 0) of `controller` kept beside its best after its last generation
// (evo::Optimizer::members, genomes included): its optimizer rebuilt for `spec` (the
// experiment the run ran, experiment_of_run) from the state the run stored. Throws Error
// when the run is not finished or its optimizer keeps no members, or the state is damaged.
[[nodiscard]] evo::Members final_members(const StoredRun& stored, const eval::ExperimentSpec& spec,
                                         const std::string& controller, int run);

// A genome file `esc run` wrote (CONTROLLER/run-NN.best.json), parsed as `j`: whether its
// checksum matches its genome, fitness and seed (true for a file of an esc before checksums,
// which has none). Throws what reading its fields throws: nlohmann::json::exception, or
// std::invalid_argument for a seed that is not one.
[[nodiscard]] bool genome_file_intact(const nlohmann::json& j);
// The seed of the evaluation genome file `j` holds the genome of; nullopt for a file of an
// esc before it was stored. Throws std::invalid_argument for a seed that is not one.
[[nodiscard]] std::optional<std::uint64_t> genome_file_seed(const nlohmann::json& j);

}  // namespace esc::app
