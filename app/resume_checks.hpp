#pragma once
// What a resume checks before it writes anything (resume.cpp): that the script is still
// there and compiles to what the run started with, under the same settings and with the
// same inputs from its dependencies, and that a carry-on only lengthens it. Each throws
// Error saying what differs.
#include <filesystem>
#include <optional>
#include <vector>

#include "app/events.hpp"
#include "app/run.hpp"
#include "compiler/compiler.hpp"
#include "runtime/store/results_db.hpp"

namespace esc::app {

// The script the run continues with: the request's, else the one it started from.
[[nodiscard]] std::filesystem::path resume_script(const ResumeRequest& r, const std::filesystem::path& stored);

// `script` compiled to resume the run; warnings go to the events. When it does not compile,
// one problem says so, with the diagnostics attached when the request asks to explain.
[[nodiscard]] compiler::CompileResult compile_to_resume(const ResumeRequest& r, const std::filesystem::path& script,
                                                        const compiler::CompileOptions& options, Events& events);

// That `spec` (compiled from `script` and its `sources`, with the stored overrides) is what
// the run started with: the same content hash and resolved settings.
void check_resumable(const eval::ExperimentSpec& spec, const std::vector<store::SourceFile>& sources,
                     const store::StoredExperiment& stored, const std::filesystem::path& script,
                     const ResumeRequest& r);

// That `spec`'s dependencies, found in `cache`, gave what the run started with.
void check_same_inputs(const eval::ExperimentSpec& spec, const store::StoredExperiment& stored,
                       const std::filesystem::path& cache, const std::filesystem::path& dir);

// The generations `spec` (as stored) is carried on to by the request: nullopt when it is
// what it already has (a plain resume). Refuses to cut a run, or to carry on one that only
// evaluates.
[[nodiscard]] std::optional<int> carry_on_to(const ResumeRequest& r, const eval::ExperimentSpec& spec);

// The cache of a resumed run: the request's, else the one it used, else the run's own.
[[nodiscard]] std::filesystem::path resume_cache(const ResumeRequest& r, const Overrides& stored);

}  // namespace esc::app
