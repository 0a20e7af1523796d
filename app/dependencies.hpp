#pragma once
// Experiments that need another experiment's results first: supervisors over evolved
// behaviors (`behavior b = evolved from experiment E controller C`) and runs that start
// from stored controllers (`start from` / `evaluate from experiment E`). Each experiment
// they need runs into the cache, or a finished run there is reused. The cache directory
// is named by a hash of the experiment's fingerprint (runtime/eval/fingerprint.hpp) and
// the esc version, so a change to what the experiment reads (its arena, fitness,
// controllers, behaviors, settings, or the genomes of its own dependencies) runs it again,
// and nothing else does. A run killed halfway is continued by the next process on the same
// machine that needs it (not under MPI, where it starts again).
#include <filesystem>
#include <functional>

#include "app/events.hpp"
#include "compiler/compiler.hpp"
#include "runtime/eval/experiment.hpp"

namespace esc::app {

struct DependencyContext {
  const compiler::CompileResult& compiled;
  // Applies the run's overrides to a dependency (as to the main experiment); throws Error.
  std::function<void(eval::ExperimentSpec&)> apply_overrides;
  // Runs an experiment into a new directory; throws Error.
  std::function<void(const eval::ExperimentSpec&, const std::filesystem::path&)> run_into;
  // Continues the run of an experiment in a directory a killed process left; false (after
  // a warning saying why) when it cannot be continued.
  std::function<bool(const eval::ExperimentSpec&, const std::filesystem::path&)> resume_into;
  std::filesystem::path cache;
  std::string version;   // part of every cache key
  Events& events;
  // Only finished runs in the cache are used; a missing one is an error (`esc replay`
  // reads what a run used and never runs anything; run_into and resume_into are not called).
  bool reuse_only = false;
};

// Gives dependency `spec` what the study condition of its user (the experiment that needs
// it) sets in it (`energy.generations 60`); what the condition sets further down goes on to
// `spec`'s own dependencies. Throws Error (kind Setting).
void apply_dependency_settings(eval::ExperimentSpec& spec, const std::vector<eval::DependencySetting>& given,
                               const std::string& user);

// Fills `spec`'s frozen behaviors and start genomes, running what it needs first
// (dependencies of dependencies before), telling `context.events` what it does. Throws
// Error (kind Dependency, or that of the problem met in running one).
void prepare_dependencies(eval::ExperimentSpec& spec, const DependencyContext& context);

// Beside the results of a dependency cache entry: the whole fingerprint it was filed under
// (its name holds a hash).
inline constexpr const char* kFingerprintFile = "fingerprint.txt";

// Whether `dir` is an entry of a dependency cache (a finished run filed under its fingerprint).
[[nodiscard]] bool is_cache_entry(const std::filesystem::path& dir);

// Where the finished run in `dir` finds what it depended on: its own deps/, or, for an entry
// of a dependency cache, the cache it sits in, beside its own dependencies.
[[nodiscard]] std::filesystem::path cache_of_run(const std::filesystem::path& dir);

}  // namespace esc::app
