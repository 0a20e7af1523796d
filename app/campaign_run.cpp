#include "app/campaign_run.hpp"

#include <ctime>
#include <optional>

#include <fmt/format.h>

#include "app/compile.hpp"
#include "app/ranks.hpp"
#include "app/version.hpp"
#include "runtime/eval/fingerprint.hpp"

namespace esc::app {

std::filesystem::path default_out(const std::string& name) {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  localtime_r(&now, &tm);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &tm);
  return std::filesystem::path("runs") / fmt::format("{}-{}", name, stamp);
}

std::string generations_text(const eval::ExperimentSpec& spec) {
  int es = -1, gp = -1;
  for (const auto& c : spec.controllers) (c.is_tree() ? gp : es) = spec.generations_for(c);
  if (es >= 0 && gp >= 0 && es != gp) return fmt::format("{} (networks) / {} (GP) generations", es, gp);
  return fmt::format("{} generation{}", spec.max_generations(), spec.max_generations() == 1 ? "" : "s");
}

std::string inputs_hash(const eval::ExperimentSpec& spec) {
  return fmt::format("{:016x}", store::content_hash(eval::fingerprint(spec)));
}

store::LaunchInfo launch_info(const Overrides& o, const std::filesystem::path& script,
                              const eval::ExperimentSpec* inputs_of) {
  store::LaunchInfo launch;
  launch.script = std::filesystem::absolute(script).lexically_normal();
  launch.overrides = to_json(o);
  if (inputs_of != nullptr && (!inputs_of->dependencies.empty() || inputs_of->start_from))
    launch.overrides["inputs"] = inputs_hash(*inputs_of);
  launch.software_version = version();
  return launch;
}

eval::CampaignOptions campaign_options(const Execution& x, const eval::ResumePoint* resume) {
  eval::CampaignOptions c;
  c.threads = x.threads;
  c.resume = resume;
  c.trace_best = true;
  c.runs_at_once = x.runs_at_once;
  return c;
}

std::int64_t generations_done(const eval::ResumePoint& point) {
  std::int64_t done = 0;
  for (const auto& f : point.finished) done += static_cast<std::int64_t>(f.result.generations.size());
  for (const auto& p : point.in_progress) done += static_cast<std::int64_t>(p.state.generations.size());
  return done;
}

eval::CampaignResult run_campaign_into(const eval::ExperimentSpec& spec, const std::string& condition,
                                       const eval::CampaignOptions& options, store::RunDirectory* dir,
                                       std::int64_t already_done, Events& events) {
  if (follower_rank() || dir == nullptr) {
    eval::CampaignListener silent;
    eval::CampaignOptions quiet = options;
    quiet.trace_best = false;
    return eval::run_campaign(spec, quiet, silent);
  }
  std::unique_ptr<Progress> progress = events.progress(spec, condition, *dir, already_done);
  eval::CampaignResult result;
  try {
    result = eval::run_campaign(spec, options, progress ? static_cast<eval::CampaignListener&>(*progress) : *dir);
  } catch (...) {
    if (progress) progress->close();
    throw;
  }
  if (progress) progress->close();
  dir->finish(result);
  return result;
}

eval::CampaignResult run_experiment(const eval::ExperimentSpec& spec, const eval::CampaignOptions& options,
                                    const std::function<store::RunDirectory()>& open, std::int64_t already_done,
                                    Events& events) {
  std::optional<store::RunDirectory> dir;
  on_rank0([&] { dir.emplace(open()); });
  eval::CampaignResult result = run_campaign_into(spec, {}, options, dir ? &*dir : nullptr, already_done, events);
  if (!follower_rank()) events.experiment_done(spec, result);
  return result;
}

DependencyContext dependency_context(const compiler::CompileResult& compiled, const Overrides& o, const Execution& x,
                                     const std::filesystem::path& cache, const std::filesystem::path& script,
                                     Events& events) {
  // Each runs into a directory of its own, renamed when finished (prepare_dependencies says
  // where it went).
  return DependencyContext{
      compiled,
      [given = for_dependencies(o)](eval::ExperimentSpec& d) {
        apply_settings(given, d, fmt::format("dependency `{}`: ", d.name));
      },
      [&compiled, &o, &x, &events, script](const eval::ExperimentSpec& d, const std::filesystem::path& dir) {
        check_memory(d);
        (void)run_experiment(
            d, campaign_options(x, nullptr),
            [&] { return store::RunDirectory(dir, d, sources_of(compiled), launch_info(o, script)); }, 0, events);
      },
      [&x, &events](const eval::ExperimentSpec& d, const std::filesystem::path& dir) {
        check_memory(d);
        try {
          store::ResultsDb db = store::ResultsDb::open(dir);
          const store::StoredExperiment stored = db.load_single();
          const eval::ResumePoint point = db.resume_point(stored, d);
          (void)run_experiment(
              d, campaign_options(x, &point),
              [&] { return store::RunDirectory::resume(dir, std::move(db), stored, point); }, generations_done(point),
              events);
          return true;
        } catch (const std::exception& e) {
          // Whatever stops it (a damaged database, a full disk), the caller runs it afresh.
          if (!follower_rank())
            events.note({Note::Kind::Warning, fmt::format("{}: cannot continue: {}", dir.string(), e.what())});
          return false;
        }
      },
      cache, version(), events};
}

std::filesystem::path run_cache(const Overrides& o, const std::filesystem::path& out) {
  return o.cache.empty() ? out / store::kDependencyCache : o.cache;
}

}  // namespace esc::app
