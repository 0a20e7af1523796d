#pragma once
// Running one experiment's campaign the way every run does: on every rank of an MPI job,
// rank 0 storing it in its directory and telling the events; with its dependencies run or
// reused first, under the same overrides.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

#include "app/dependencies.hpp"
#include "app/events.hpp"
#include "app/settings.hpp"
#include "compiler/compiler.hpp"
#include "runtime/eval/campaign.hpp"
#include "runtime/store/run_directory.hpp"

namespace esc::app {

// How a campaign runs on this machine (never what it computes).
struct Execution {
  int threads = 0;        // 0: all cores
  int runs_at_once = 0;   // 0: as many as keep every worker busy
};

// runs/<name>-<local time>.
[[nodiscard]] std::filesystem::path default_out(const std::string& name);

// "250 generations" ("1 generation"), or "250 (networks) / 50 (GP) generations" when the
// algorithms differ.
[[nodiscard]] std::string generations_text(const eval::ExperimentSpec& spec);

// What an experiment received from the experiments it depends on (frozen behaviors, start
// genomes), as a hash of its fingerprint: a resume must find the same.
[[nodiscard]] std::string inputs_hash(const eval::ExperimentSpec& spec);

// How a run was started, for its database; with the hash of what `inputs_of` received from
// its dependencies, when it has any.
[[nodiscard]] store::LaunchInfo launch_info(const Overrides& o, const std::filesystem::path& script,
                                            const eval::ExperimentSpec* inputs_of = nullptr);

[[nodiscard]] eval::CampaignOptions campaign_options(const Execution& x, const eval::ResumePoint* resume);

// Generations finished before a resume: the progress starts from them.
[[nodiscard]] std::int64_t generations_done(const eval::ResumePoint& point);

// Runs `spec`'s campaign (study condition `condition`, or none) on every rank. Rank 0
// stores it in `dir` behind the events' progress (`already_done`: generations finished
// before this process); the other ranks evaluate their share and store nothing (`dir` is
// null there).
eval::CampaignResult run_campaign_into(const eval::ExperimentSpec& spec, const std::string& condition,
                                       const eval::CampaignOptions& options, store::RunDirectory* dir,
                                       std::int64_t already_done, Events& events);

// Runs `spec` into the directory `open` makes (on rank 0), and tells the events it is done.
eval::CampaignResult run_experiment(const eval::ExperimentSpec& spec, const eval::CampaignOptions& options,
                                    const std::function<store::RunDirectory()>& open, std::int64_t already_done,
                                    Events& events);

// How dependencies run: with the same overrides and execution, each into its own directory
// under `cache`.
[[nodiscard]] DependencyContext dependency_context(const compiler::CompileResult& compiled, const Overrides& o,
                                                  const Execution& x, const std::filesystem::path& cache,
                                                  const std::filesystem::path& script, Events& events);

// The cache of a new run into `out`: the overrides' cache, else OUT/deps.
[[nodiscard]] std::filesystem::path run_cache(const Overrides& o, const std::filesystem::path& out);

}  // namespace esc::app
