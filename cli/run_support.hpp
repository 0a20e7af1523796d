#pragma once
// What `esc run` does the same way for an experiment and for a study: the command line's
// overrides (applied, stored, replayed on resume), the campaign's options, the dependencies'
// context, and running one campaign on every rank of an MPI job with rank 0 writing.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/dependencies.hpp"
#include "cli/experiment_setup.hpp"
#include "compiler/compiler.hpp"
#include "runtime/eval/campaign.hpp"
#include "runtime/store/results_db.hpp"
#include "runtime/store/run_directory.hpp"

namespace esc::cli {

// runs/<name>-<local time>.
[[nodiscard]] std::filesystem::path default_out(const std::string& name);

// What an experiment received from the experiments it depends on (frozen behaviors, start
// genomes), as a hash of its fingerprint: a resume must find the same.
[[nodiscard]] std::string inputs_hash(const eval::ExperimentSpec& spec);

// The command-line settings as stored in the database, to be applied again on resume.
[[nodiscard]] nlohmann::ordered_json overrides_json(const RunOptions& o);


// How the campaign runs on this machine (never what it computes).
[[nodiscard]] eval::CampaignOptions campaign_options(const RunOptions& o, const eval::ResumePoint* resume);

// Generations finished before a resume: the progress starts from them.
[[nodiscard]] std::int64_t generations_done(const eval::ResumePoint& point);

// How dependencies run: with the same command-line overrides and thread count, each into
// its own directory under `cache`.
[[nodiscard]] DependencyContext dependency_context(const compiler::CompileResult& compiled, const RunOptions& o,
                                                  const std::filesystem::path& cache,
                                                  const std::filesystem::path& script);

// How a run was started, for its database; with the hash of what `inputs_of` received from
// its dependencies, when it has any.
[[nodiscard]] store::LaunchInfo launch_info(const RunOptions& o, const std::filesystem::path& script,
                                            const eval::ExperimentSpec* inputs_of = nullptr);

// The script a run in `o.resume` continues with: FILE when given, else the one it started
// from; nullopt after printing an error when that one is gone.
[[nodiscard]] std::optional<std::filesystem::path> resume_script(const RunOptions& o,
                                                                 const std::filesystem::path& stored);

// `script` compiled to resume the run in `o.resume`. When it does not compile, one line says
// so (the diagnostics follow with --verbose); warnings are printed as a run prints them.
[[nodiscard]] compiler::CompileResult compile_to_resume(const RunOptions& o, const std::filesystem::path& script);

// Whether `spec` (compiled from `script` and its `sources`, with the stored overrides) is
// what the run in `o.resume` started with: the same content hash and resolved settings.
// Prints what differs otherwise, in one line (which files changed follow with --verbose).
[[nodiscard]] bool resumable(const eval::ExperimentSpec& spec, const std::vector<store::SourceFile>& sources,
                             const store::StoredExperiment& stored, const std::filesystem::path& script,
                             const RunOptions& o);

// Whether `spec`'s dependencies, found in `cache`, gave what the run in `dir` started with
// (the stored inputs hash); prints the problem otherwise.
[[nodiscard]] bool same_inputs(const eval::ExperimentSpec& spec, const store::StoredExperiment& stored,
                               const std::filesystem::path& cache, const std::filesystem::path& dir);

// The cache of a resumed run: --cache, else the one it used, else cache_of_run(DIR).
[[nodiscard]] std::filesystem::path resume_cache(const RunOptions& o, const RunOptions& replay);

// The cache of a new run into `out`: --cache, else OUT/deps.
[[nodiscard]] std::filesystem::path run_cache(const RunOptions& o, const std::filesystem::path& out);

// Rank 0 (or a lone process) calls `open`; every rank of an MPI job learns whether it
// succeeded. False after printing the error.
[[nodiscard]] bool open_on_rank0(const std::function<void()>& open);

// Runs `spec`'s campaign on every rank. Rank 0 reports to `dir` through the progress
// printer (`already_done`: generations finished before this process); the other ranks
// evaluate their share and write nothing.
eval::CampaignResult campaign_on_all_ranks(const eval::ExperimentSpec& spec, const eval::CampaignOptions& options,
                                           store::RunDirectory* dir, std::int64_t already_done);

// `--resume DIR --generations G`: the generations `spec` (as stored) is carried on to, after
// checking that G carries every controller on (never cuts it) and that the experiment
// evolves; nullopt when G is what it already has (a plain resume), -1 after printing an error.
[[nodiscard]] std::optional<int> carry_on_to(const RunOptions& o, const eval::ExperimentSpec& spec);

// `spec` run for `generations` (the ES's and the GP's) when given; false when refused.
[[nodiscard]] bool set_generations(eval::ExperimentSpec& spec, std::optional<int> generations);

// A study's run and resume (study_command.cpp).
int run_study(const RunOptions& o, compiler::CompileResult& compiled, eval::StudySpec& study);
int resume_study(const RunOptions& o, std::vector<store::StoredExperiment> stored);

}  // namespace esc::cli
