#include "app/resume_checks.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "app/campaign_run.hpp"
#include "app/compile.hpp"
#include "app/dependencies.hpp"
#include "app/error.hpp"
#include "app/ranks.hpp"
#include "runtime/eval/settings_history.hpp"

namespace esc::app {

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

std::filesystem::path resume_script(const ResumeRequest& r, const std::filesystem::path& stored) {
  if (!r.script.empty()) return r.script;
  std::error_code ec;
  if (std::filesystem::exists(stored, ec)) return stored;
  throw Error(ErrorKind::Results,
              fmt::format("the script the run in {} started from, {}, is gone; give its new place: esc run FILE "
                          "--resume {} (a copy of every file it read is in {}/sources)",
                          r.dir.string(), stored.string(), r.dir.string(), r.dir.string()));
}

compiler::CompileResult compile_to_resume(const ResumeRequest& r, const std::filesystem::path& script,
                                          const compiler::CompileOptions& options, Events& events) {
  compiler::CompileResult compiled = compiler::compile_file(script, options);
  if (compiled.ok()) {
    if (!compiled.diagnostics.empty() && !follower_rank()) events.warnings(compiled);
    return compiled;
  }
  const auto is_error = [](const compiler::Diagnostic& d) { return d.severity == compiler::Severity::Error; };
  const auto first = std::find_if(compiled.diagnostics.begin(), compiled.diagnostics.end(), is_error);
  const auto errors = std::count_if(first, compiled.diagnostics.end(), is_error);
  std::string message = fmt::format(
      "{} no longer compiles: {} ({} error{}{}); the run in {} resumes only with the script it started with (a copy is "
      "in {}/sources)",
      script.string(), first->message, errors, errors == 1 ? "" : "s", r.explain ? "" : ", all shown with --verbose",
      r.dir.string(), r.dir.string());
  throw Error(ErrorKind::Script, {{std::move(message), {}}}, {},
              r.explain ? std::make_shared<const compiler::CompileResult>(std::move(compiled)) : nullptr);
}

void check_resumable(const eval::ExperimentSpec& spec, const std::vector<store::SourceFile>& sources,
                     const store::StoredExperiment& stored, const std::filesystem::path& script,
                     const ResumeRequest& r) {
  const std::filesystem::path& dir = r.dir;
  const std::string hash = store::campaign_hash(spec.name, sources);
  if (hash != stored.content_hash) {
    std::vector<std::string> details;
    if (r.explain) {
      for (const std::string& line : changed_sources(sources, stored.sources)) details.push_back("  " + line);
      details.push_back(fmt::format("  content hash {}, stored {}", hash, stored.content_hash));
    }
    throw Error(ErrorKind::Results,
                {{fmt::format("{} has changed since the run in {} started; a run resumes only with the script it "
                              "started with (a copy is in {}/sources{})",
                              script.string(), dir.string(), dir.string(), r.explain ? "" : "; --verbose names the files"),
                  {}}},
                std::move(details));
  }
  if (eval::same_settings(spec.resolved_settings, stored.settings)) return;
  for (const auto& [key, value] : spec.resolved_settings) {
    const auto it = stored.settings.find(key);
    if (it == stored.settings.end() ? !eval::as_before_it_existed(key, value) : it->second != value)
      throw Error(ErrorKind::Results, fmt::format("setting `{}` is now `{}` but the run in {} used `{}`; cannot resume",
                                                  key, value, dir.string(),
                                                  it == stored.settings.end() ? "nothing" : it->second));
  }
  throw Error(ErrorKind::Results, "the settings differ from the stored ones; cannot resume");
}

void check_same_inputs(const eval::ExperimentSpec& spec, const store::StoredExperiment& stored,
                       const std::filesystem::path& cache, const std::filesystem::path& dir) {
  if (!stored.overrides.contains("inputs") || stored.overrides["inputs"] == inputs_hash(spec)) return;
  throw Error(ErrorKind::Dependency,
              fmt::format("the evolved behaviors or start genomes found in {} differ from those the run in {} started "
                          "with; cannot resume (give --cache the directory the run used)",
                          cache.string(), dir.string()));
}

std::optional<int> carry_on_to(const ResumeRequest& r, const eval::ExperimentSpec& spec) {
  if (!r.generations) return std::nullopt;
  bool more = false;
  for (const control::ControllerSpec& c : spec.controllers) {
    if (*r.generations < spec.generations_for(c))
      throw Error(ErrorKind::Setting,
                  fmt::format("the runs of {} in {} have {} generations; --generations {} would cut them: a run is "
                              "carried on to more generations, never shortened (nothing was changed)",
                              c.name, r.dir.string(), spec.generations_for(c), *r.generations));
    more = more || *r.generations > spec.generations_for(c);
  }
  if (more && spec.evaluates_only())
    throw Error(ErrorKind::Setting, fmt::format("experiment {} only evaluates stored controllers (`evaluate from`): it "
                                                "has no generations to carry on",
                                                spec.name));
  if (!more) return std::nullopt;
  return *r.generations;
}

std::filesystem::path resume_cache(const ResumeRequest& r, const Overrides& stored) {
  return !r.cache.empty() ? r.cache : !stored.cache.empty() ? stored.cache : cache_of_run(r.dir);
}

}  // namespace esc::app
