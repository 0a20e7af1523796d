#include "cli/run_support.hpp"

#include <algorithm>
#include <ctime>

#include <unistd.h>

#include <fmt/format.h>

#include "cli/end_table.hpp"
#include "cli/load.hpp"
#include "cli/progress.hpp"
#include "runtime/dist/mpi_session.hpp"
#include "runtime/eval/fingerprint.hpp"
#include "runtime/eval/settings_history.hpp"
#include "runtime/store/seed_json.hpp"

namespace esc::cli {

std::filesystem::path default_out(const std::string& name) {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  localtime_r(&now, &tm);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &tm);
  return std::filesystem::path("runs") / fmt::format("{}-{}", name, stamp);
}

std::string inputs_hash(const eval::ExperimentSpec& spec) {
  return fmt::format("{:016x}", store::content_hash(eval::fingerprint(spec)));
}

nlohmann::ordered_json overrides_json(const RunOptions& o) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  if (o.runs) j["runs"] = *o.runs;
  if (o.generations) j["generations"] = *o.generations;
  if (o.seed) j["seed"] = store::seed_json(*o.seed);
  j["set"] = o.settings;
  if (!o.controllers.empty()) j["controllers"] = o.controllers;
  // Where dependencies were run or reused, so that a resume finds them again.
  if (!o.cache.empty()) j["cache"] = std::filesystem::absolute(o.cache).lexically_normal().string();
  return j;
}

eval::CampaignOptions campaign_options(const RunOptions& o, const eval::ResumePoint* resume) {
  eval::CampaignOptions c;
  c.threads = o.threads;
  c.resume = resume;
  c.trace_best = true;
  c.runs_at_once = o.runs_at_once;
  return c;
}

std::int64_t generations_done(const eval::ResumePoint& point) {
  std::int64_t done = 0;
  for (const auto& f : point.finished) done += static_cast<std::int64_t>(f.result.generations.size());
  for (const auto& p : point.in_progress) done += static_cast<std::int64_t>(p.state.generations.size());
  return done;
}

store::LaunchInfo launch_info(const RunOptions& o, const std::filesystem::path& script,
                              const eval::ExperimentSpec* inputs_of) {
  store::LaunchInfo launch;
  launch.script = std::filesystem::absolute(script).lexically_normal();
  launch.overrides = overrides_json(o);
  if (inputs_of != nullptr && (!inputs_of->dependencies.empty() || inputs_of->start_from))
    launch.overrides["inputs"] = inputs_hash(*inputs_of);
  launch.software_version = ESC_VERSION_STRING;
  return launch;
}

std::optional<std::filesystem::path> resume_script(const RunOptions& o, const std::filesystem::path& stored) {
  if (!o.file.empty()) return o.file;
  std::error_code ec;
  if (std::filesystem::exists(stored, ec)) return stored;
  complain("esc: error: the script the run in {} started from, {}, is gone; give its new place: esc run FILE "
           "--resume {} (a copy of every file it read is in {}/sources)\n",
           o.resume.string(), stored.string(), o.resume.string(), o.resume.string());
  return std::nullopt;
}

compiler::CompileResult compile_to_resume(const RunOptions& o, const std::filesystem::path& script) {
  compiler::CompileResult compiled = compiler::compile_file(script, default_compile_options());
  const std::string diagnostics =
      compiler::render_all(compiled.diagnostics, compiled.sources, isatty(STDERR_FILENO) != 0);
  // Rendered source lines go out as they are (complain() would shorten `quoted` names).
  const auto print_diagnostics = [&] {
    if (!follower_rank()) fmt::print(stderr, "{}", diagnostics);
  };
  if (compiled.ok()) {
    print_diagnostics();   // warnings, as a run prints them
    return compiled;
  }
  const auto first = std::find_if(compiled.diagnostics.begin(), compiled.diagnostics.end(),
                                  [](const compiler::Diagnostic& d) { return d.severity == compiler::Severity::Error; });
  const auto errors = std::count_if(first, compiled.diagnostics.end(),
                                    [](const compiler::Diagnostic& d) { return d.severity == compiler::Severity::Error; });
  complain("esc: error: {} no longer compiles: {} ({} error{}{}); the run in {} resumes only with the script it "
           "started with (a copy is in {}/sources)\n",
           script.string(), first->message, errors, errors == 1 ? "" : "s", o.verbose ? "" : ", all shown with --verbose",
           o.resume.string(), o.resume.string());
  if (o.verbose) print_diagnostics();
  return compiled;
}

namespace {

// The files of `now` whose text the run did not read, and the files it read that `now`
// does not hold: what a content-hash mismatch comes from.
std::vector<std::string> changed_sources(const std::vector<store::SourceFile>& now,
                                         const std::vector<store::SourceFile>& then) {
  const auto holds = [](const std::vector<store::SourceFile>& files, const store::SourceFile& f) {
    return std::any_of(files.begin(), files.end(), [&](const store::SourceFile& g) { return g.text == f.text; });
  };
  std::vector<std::string> changed;
  for (const store::SourceFile& f : now)
    if (!holds(then, f)) changed.push_back(fmt::format("changed or new: {}", f.name.string()));
  for (const store::SourceFile& f : then)
    if (!holds(now, f)) changed.push_back(fmt::format("as the run read it: {}", f.name.string()));
  return changed;
}

}  // namespace

bool resumable(const eval::ExperimentSpec& spec, const std::vector<store::SourceFile>& sources,
               const store::StoredExperiment& stored, const std::filesystem::path& script, const RunOptions& o) {
  const std::filesystem::path& dir = o.resume;
  const std::string hash = store::campaign_hash(spec.name, sources);
  if (hash != stored.content_hash) {
    complain("esc: error: {} has changed since the run in {} started; a run resumes only with the script it started "
             "with (a copy is in {}/sources{})\n",
             script.string(), dir.string(), dir.string(), o.verbose ? "" : "; --verbose names the files");
    if (o.verbose) {
      for (const std::string& line : changed_sources(sources, stored.sources)) complain("  {}\n", line);
      complain("  content hash {}, stored {}\n", hash, stored.content_hash);
    }
    return false;
  }
  if (eval::same_settings(spec.resolved_settings, stored.settings)) return true;
  for (const auto& [key, value] : spec.resolved_settings) {
    const auto it = stored.settings.find(key);
    if (it == stored.settings.end() ? !eval::as_before_it_existed(key, value) : it->second != value) {
      complain("esc: error: setting `{}` is now `{}` but the run in {} used `{}`; cannot resume\n", key, value,
               dir.string(), it == stored.settings.end() ? "nothing" : it->second);
      return false;
    }
  }
  complain("esc: error: the settings differ from the stored ones; cannot resume\n");
  return false;
}

bool same_inputs(const eval::ExperimentSpec& spec, const store::StoredExperiment& stored,
                 const std::filesystem::path& cache, const std::filesystem::path& dir) {
  if (!stored.overrides.contains("inputs") || stored.overrides["inputs"] == inputs_hash(spec)) return true;
  complain("esc: error: the evolved behaviors or start genomes found in {} differ from those the run in {} "
           "started with; cannot resume (give --cache the directory the run used)\n",
           cache.string(), dir.string());
  return false;
}

std::filesystem::path resume_cache(const RunOptions& o, const RunOptions& replay) {
  return !o.cache.empty() ? o.cache : !replay.cache.empty() ? replay.cache : cache_of_run(o.resume);
}

std::filesystem::path run_cache(const RunOptions& o, const std::filesystem::path& out) {
  return o.cache.empty() ? out / store::kDependencyCache : o.cache;
}

bool open_on_rank0(const std::function<void()>& open) {
  const dist::MpiSession* mpi = dist::MpiSession::current();
  const bool job = mpi != nullptr && mpi->active();
  if (follower_rank()) return mpi->all_ok(true);
  try {
    open();
  } catch (const std::exception& e) {
    // Every rank learns of it and ends normally: no MPI_Abort racing their MPI_Finalize
    // (with Open MPI that can leave mpirun waiting forever).
    complain("esc: error: {}\n", e.what());
    if (job) (void)mpi->all_ok(false);
    return false;
  }
  if (job) (void)mpi->all_ok(true);
  return true;
}

eval::CampaignResult campaign_on_all_ranks(const eval::ExperimentSpec& spec, const eval::CampaignOptions& options,
                                           store::RunDirectory* dir, std::int64_t already_done) {
  if (follower_rank() || dir == nullptr) {
    eval::CampaignListener silent;
    eval::CampaignOptions quiet = options;
    quiet.trace_best = false;
    return eval::run_campaign(spec, quiet, silent);
  }
  ProgressPrinter progress(spec, *dir, isatty(STDOUT_FILENO) != 0, already_done);
  eval::CampaignResult result = eval::run_campaign(spec, options, progress);
  progress.close();
  dir->finish(result);
  return result;
}

DependencyContext dependency_context(const compiler::CompileResult& compiled, const RunOptions& o,
                                     const std::filesystem::path& cache, const std::filesystem::path& script) {
  // Each runs into a directory of its own, renamed when finished (prepare_dependencies says
  // where it went).
  const auto run = [](const eval::ExperimentSpec& d, const eval::CampaignOptions& options,
                      const std::function<store::RunDirectory()>& open, std::int64_t done) {
    if (!fits_in_memory(d)) return kExitBadInput;
    std::optional<store::RunDirectory> dir;
    if (!open_on_rank0([&] { dir.emplace(open()); })) return kExitBadInput;
    const eval::CampaignResult result = campaign_on_all_ranks(d, options, dir ? &*dir : nullptr, done);
    if (!follower_rank()) print_table(d, result);
    return kExitOk;
  };
  return DependencyContext{
      compiled, [&o](eval::ExperimentSpec& d) { return apply_overrides(o, d); },
      [&compiled, &o, script, run](const eval::ExperimentSpec& d, const std::filesystem::path& dir) {
        return run(d, campaign_options(o, nullptr),
                   [&] { return store::RunDirectory(dir, d, sources_of(compiled), launch_info(o, script)); },
                   0);
      },
      [&o, run](const eval::ExperimentSpec& d, const std::filesystem::path& dir) {
        try {
          store::ResultsDb db = store::ResultsDb::open(dir);
          const store::StoredExperiment stored = db.load_single();
          const eval::ResumePoint point = db.resume_point(stored, d);
          return run(d, campaign_options(o, &point),
                     [&] { return store::RunDirectory::resume(dir, std::move(db), stored, point); },
                     generations_done(point));
        } catch (const std::exception& e) {
          // Whatever stops it (a damaged database, a full disk), the caller runs it afresh.
          complain("esc: {}: cannot continue: {}\n", dir.string(), e.what());
          return kExitBadInput;
        }
      },
      cache, ESC_VERSION_STRING};
}

std::optional<int> carry_on_to(const RunOptions& o, const eval::ExperimentSpec& spec) {
  if (!o.generations) return std::nullopt;
  bool more = false;
  for (const control::ControllerSpec& c : spec.controllers) {
    if (*o.generations < spec.generations_for(c)) {
      complain("esc: error: the runs of {} in {} have {} generations; --generations {} would cut them: a run is "
               "carried on to more generations, never shortened (nothing was changed)\n",
               c.name, o.resume.string(), spec.generations_for(c), *o.generations);
      return -1;
    }
    more = more || *o.generations > spec.generations_for(c);
  }
  if (more && spec.evaluates_only()) {
    complain("esc: error: experiment {} only evaluates stored controllers (`evaluate from`): it has no generations "
             "to carry on\n", spec.name);
    return -1;
  }
  if (!more) return std::nullopt;
  return *o.generations;
}

bool set_generations(eval::ExperimentSpec& spec, std::optional<int> generations) {
  return !generations || compiler::apply_setting(spec, "generations", std::to_string(*generations)).empty();
}

}  // namespace esc::cli
