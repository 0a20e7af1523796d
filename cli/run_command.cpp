#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <functional>
#include <iostream>
#include <memory>
#include <variant>
#include <optional>
#include <vector>

#include <unistd.h>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "cli/dependencies.hpp"
#include "cli/load.hpp"
#include "cli/experiment_setup.hpp"
#include "cli/progress.hpp"
#include "runtime/dist/mpi_session.hpp"
#include "runtime/eval/campaign.hpp"
#include "runtime/eval/fingerprint.hpp"
#include "runtime/report/comparisons.hpp"
#include "runtime/report/statistics.hpp"
#include "runtime/store/run_directory.hpp"

namespace esc::cli {

namespace {

std::string number_or_na(double x, int decimals) {
  return std::isnan(x) ? "n/a" : fmt::format("{:.{}f}", x, decimals);
}

std::string p_text(double p) {
  if (std::isnan(p)) return "n/a";
  return p < 1e-4 ? fmt::format("{:.1e}", p) : fmt::format("{:.4f}", p);
}

// Share of control steps each action or behavior acted, over the best evaluations of all
// runs (symbolic heads and supervisors).
void print_usage(const eval::CampaignResult& result) {
  bool header = false;
  for (const auto& c : result.controllers) {
    std::vector<std::int64_t> steps(c.choices.size(), 0);
    for (const auto& r : c.runs)
      for (std::size_t i = 0; i < r.action_usage.size() && i < steps.size(); ++i) steps[i] += r.action_usage[i];
    std::int64_t total = 0;
    for (std::int64_t n : steps) total += n;
    if (total == 0) continue;
    if (!header) fmt::print("\nbehavior usage (share of steps in each run's best evaluation)\n");
    header = true;
    // Wrapped (sensitivity.esc's supervisors choose among 24 behaviors).
    constexpr std::size_t kWidth = 100;
    std::string line = fmt::format("{:<12} ", c.name);
    const std::size_t indent = line.size();
    for (std::size_t i = 0; i < steps.size(); ++i) {
      const std::string entry = fmt::format("{} {:.0f}%{}", c.choices[i],
                                            100.0 * static_cast<double>(steps[i]) / static_cast<double>(total),
                                            i + 1 < steps.size() ? "," : "");
      if (line.size() > indent && line.size() + 1 + entry.size() > kWidth) {
        fmt::print("{}\n", line);
        line = std::string(indent, ' ');
      }
      line += (line.size() > indent ? " " : "") + entry;
    }
    fmt::print("{}\n", line);
  }
}

// "250 generations", or "250 (ES) / 50 (GP) generations" when the algorithms differ.
std::string generations_text(const eval::ExperimentSpec& spec) {
  int es = -1, gp = -1;
  for (const auto& c : spec.controllers) (c.is_tree() ? gp : es) = spec.generations_for(c);
  if (es >= 0 && gp >= 0 && es != gp) return fmt::format("{} (ES) / {} (GP) generations", es, gp);
  return fmt::format("{} generations", spec.max_generations());
}

// The best tree of each run of the tree controllers, as script code.
void print_trees(const eval::CampaignResult& result) {
  for (const auto& c : result.controllers)
    for (const auto& r : c.runs)
      if (!r.best_tree.empty())
        fmt::print("{:<12} run {} best tree (fitness {:.1f}): {}\n", c.name, r.run + 1, r.best_fitness, r.best_tree);
}

void print_table(const eval::ExperimentSpec& spec, const eval::CampaignResult& result) {
  fmt::print("\n{}: {} run{} x {}, {} epochs x {} steps, seed {}\n", spec.name, spec.runs,
             spec.runs == 1 ? "" : "s", generations_text(spec), spec.epochs, spec.steps, spec.seed);
  fmt::print("{:<12} {:<14} {:>6}  {:>22}  {:>10}  {:>10}\n", "controller", "architecture", "genes",
             "best fitness mean ± sd", "median", "best run");
  std::vector<std::vector<double>> finals;
  for (const auto& c : result.controllers) {
    std::vector<double> best;
    for (const auto& r : c.runs) best.push_back(r.best_fitness);
    const report::Summary s = report::summarise(best);
    fmt::print("{:<12} {:<14} {:>6}  {:>12.1f} ± {:<7.1f}  {:>10.1f}  {:>10.1f}\n", c.name, c.architecture,
               c.genome_size, s.mean, s.sd, s.median, s.max);
    finals.push_back(std::move(best));
  }
  print_usage(result);
  if (std::any_of(spec.controllers.begin(), spec.controllers.end(), [](const auto& c) { return c.is_tree(); })) {
    fmt::print("\n");
    print_trees(result);
  }
  if (result.controllers.size() < 2) return;
  fmt::print("\n{:<26} {:>9} {:>7} {:>10} {:>10}  {:>7} {:>10} {:>10}  {:>5}\n", "pairwise (two-sided)", "Welch t",
             "df", "p", "p Holm", "M-W U", "p", "p Holm", "A12");
  for (const report::Comparison& c : report::compare(finals, report::all_pairs(finals.size())))
    fmt::print("{:<26} {:>9} {:>7} {:>10} {:>10}  {:>7} {:>10} {:>10}  {:>5}\n",
               fmt::format("{} vs {}", result.controllers[c.a].name, result.controllers[c.b].name),
               number_or_na(c.welch.statistic, 3), number_or_na(c.welch.df, 1), p_text(c.welch.p_value),
               p_text(c.welch_p_holm), number_or_na(c.mann_whitney.statistic, 1), p_text(c.mann_whitney.p_value),
               p_text(c.mann_whitney_p_holm), number_or_na(c.a12, 2));
  const std::size_t pairs = finals.size() * (finals.size() - 1) / 2;
  fmt::print("Holm: p adjusted over the {} pair{} shown, for each test. Mann-Whitney p exact when a sample has at most "
             "8 runs and no ties. A12: chance the first beats the second.\n",
             pairs, pairs == 1 ? "" : "s");
}

std::filesystem::path default_out(const std::string& experiment) {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  localtime_r(&now, &tm);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &tm);
  return std::filesystem::path("runs") / fmt::format("{}-{}", experiment, stamp);
}

// What an experiment received from the experiments it depends on (frozen behaviors, start
// genomes), as a hash of its fingerprint: a resume must find the same.
std::string inputs_hash(const eval::ExperimentSpec& spec) {
  return fmt::format("{:016x}", store::content_hash(eval::fingerprint(spec)));
}

// The command-line settings as stored in the database, to be applied again on resume.
nlohmann::ordered_json overrides_json(const RunOptions& o) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  if (o.runs) j["runs"] = *o.runs;
  if (o.generations) j["generations"] = *o.generations;
  if (o.seed) j["seed"] = *o.seed;
  j["set"] = o.settings;
  // Where dependencies were run or reused, so that a resume finds them again.
  if (!o.cache.empty()) j["cache"] = std::filesystem::absolute(o.cache).lexically_normal().string();
  return j;
}

bool live_progress() { return isatty(STDOUT_FILENO) != 0; }

// Runs the campaign on every rank of an MPI job, or alone. Rank 0 (or the lone process)
// opens the run directory with `open`, writes every result and prints the progress and
// the table; the other ranks evaluate their share of each generation and write nothing.
// If `open` fails on rank 0, every rank stops. `out`: where to tell the user the results
// are (nothing when empty).
int run_everywhere(const eval::ExperimentSpec& spec, const eval::CampaignOptions& options,
                   const std::function<store::RunDirectory()>& open, std::int64_t already_done,
                   const std::filesystem::path& out) {
  const dist::MpiSession* mpi = dist::MpiSession::current();
  const bool job = mpi != nullptr && mpi->active();
  if (follower_rank()) {
    if (!mpi->all_ok(true)) return kExitBadInput;
    eval::CampaignListener silent;
    eval::CampaignOptions quiet = options;
    quiet.trace_best = false;
    (void)eval::run_campaign(spec, quiet, silent);
    return kExitOk;
  }
  std::optional<store::RunDirectory> dir;
  try {
    dir.emplace(open());
  } catch (const std::exception& e) {
    // Every rank learns of it and ends normally: no MPI_Abort racing their MPI_Finalize
    // (with Open MPI that can leave mpirun waiting forever).
    complain("esc: error: {}\n", e.what());
    if (job) (void)mpi->all_ok(false);
    return kExitBadInput;
  }
  if (job) (void)mpi->all_ok(true);
  ProgressPrinter progress(spec, *dir, live_progress(), already_done);
  const eval::CampaignResult result = eval::run_campaign(spec, options, progress);
  progress.close();
  dir->finish(result);
  print_table(spec, result);
  if (!out.empty()) fmt::print("\nresults: {}/summary.json (report: esc report {})\n", out.string(), out.string());
  return kExitOk;
}

// How the campaign runs on this machine (never what it computes).
eval::CampaignOptions campaign_options(const RunOptions& o, const eval::ResumePoint* resume) {
  eval::CampaignOptions c;
  c.threads = o.threads;
  c.resume = resume;
  c.trace_best = true;
  c.runs_at_once = o.runs_at_once;
  return c;
}

// Generations finished before a resume: the progress starts from them.
std::int64_t generations_done(const eval::ResumePoint& point) {
  std::int64_t done = 0;
  for (const auto& f : point.finished) done += static_cast<std::int64_t>(f.result.generations.size());
  for (const auto& p : point.in_progress) done += static_cast<std::int64_t>(p.state.generations.size());
  return done;
}

// How dependencies run: with the same command-line overrides and thread count, each into
// its own directory under `cache`.
DependencyContext dependency_context(const compiler::CompileResult& compiled, const RunOptions& o,
                                     const std::filesystem::path& cache, const std::filesystem::path& script) {
  return DependencyContext{
      compiled, [&o](eval::ExperimentSpec& d) { return apply_overrides(o, d); },
      [&compiled, &o, script](const eval::ExperimentSpec& d, const std::filesystem::path& dir) {
        store::LaunchInfo launch;
        launch.script = std::filesystem::absolute(script).lexically_normal();
        launch.overrides = overrides_json(o);
        launch.software_version = ESC_VERSION_STRING;
        return run_everywhere(
            d, campaign_options(o, nullptr), [&] { return store::RunDirectory(dir, d, sources_of(compiled), launch); }, 0,
            {});   // it is renamed when finished: prepare_dependencies says where it went
      },
      [&o](const eval::ExperimentSpec& d, const std::filesystem::path& dir) {
        try {
          store::ResultsDb db = store::ResultsDb::open(dir);
          const store::StoredExperiment stored = db.load_single();
          const eval::ResumePoint point = stored.resume_point();
          return run_everywhere(
              d, campaign_options(o, &point), [&] { return store::RunDirectory::resume(dir, std::move(db), stored); },
              generations_done(point), {});
        } catch (const std::exception& e) {
          // Whatever stops it (a damaged database, a full disk), the caller runs it afresh.
          complain("esc: {}: cannot continue: {}\n", dir.string(), e.what());
          return kExitBadInput;
        }
      },
      cache, ESC_VERSION_STRING};
}

int resume_command(const RunOptions& o) {
  if (o.runs || o.generations || o.seed || !o.settings.empty() || !o.experiment.empty() || !o.out.empty()) {
    complain("esc: error: --resume continues a run with its own settings: --runs, --generations, --seed, "
                       "--set, --experiment and --out cannot be given with it\n");
    return kExitUsage;
  }
  store::ResultsDb db = store::ResultsDb::open(o.resume);
  const store::StoredExperiment stored = db.load_single();
  const std::filesystem::path script = o.file.empty() ? stored.script : o.file;
  if (stored.finished()) {
    say("esc: {} is complete ({} x {} runs x {} generations); nothing to resume\n", o.resume.string(),
               stored.controllers.size(), stored.runs, stored.generations);
    return kExitOk;
  }

  std::error_code ec;
  if (o.file.empty() && !std::filesystem::exists(script, ec)) {
    complain("esc: error: the script the run in {} started from, {}, is gone; give its new place: esc run FILE "
             "--resume {} (a copy of every file it read is in {}/sources)\n",
             o.resume.string(), script.string(), o.resume.string(), o.resume.string());
    return kExitBadInput;
  }
  compiler::CompileResult compiled = load_script(script);
  if (!compiled.ok()) return kExitBadInput;
  eval::ExperimentSpec* spec = pick_experiment(compiled, script, stored.name);
  if (spec == nullptr) return kExitBadInput;
  RunOptions replay = stored_overrides(stored, o.resume);
  if (!apply_overrides(replay, *spec)) return kExitBadInput;
  replay.threads = o.threads;
  replay.runs_at_once = o.runs_at_once;

  const std::vector<store::SourceFile> sources = sources_of(compiled);
  const std::string hash = store::campaign_hash(spec->name, sources);
  if (hash != stored.content_hash) {
    complain("esc: error: {} has changed since the run in {} started (content hash {}, stored {}); a run resumes "
             "only with the script it started with (a copy is in {}/sources)\n",
             script.string(), o.resume.string(), hash, stored.content_hash, o.resume.string());
    return kExitBadInput;
  }
  if (spec->resolved_settings != stored.settings) {
    for (const auto& [key, value] : spec->resolved_settings) {
      const auto it = stored.settings.find(key);
      if (it == stored.settings.end() || it->second != value) {
        complain("esc: error: setting `{}` is now `{}` but the run in {} used `{}`; cannot resume\n", key,
                 value, o.resume.string(), it == stored.settings.end() ? "nothing" : it->second);
        return kExitBadInput;
      }
    }
    complain("esc: error: the settings differ from the stored ones; cannot resume\n");
    return kExitBadInput;
  }
  // Dependencies last: a script that cannot resume should not first run them.
  const std::filesystem::path cache = !o.cache.empty() ? o.cache : !replay.cache.empty() ? replay.cache : o.resume / "deps";
  if (!prepare_dependencies(*spec, dependency_context(compiled, replay, cache, script))) return kExitBadInput;
  if (stored.overrides.contains("inputs") && stored.overrides["inputs"] != inputs_hash(*spec)) {
    complain("esc: error: the evolved behaviors or start genomes found in {} differ from those the run in {} "
             "started with; cannot resume (give --cache the directory the run used)\n",
             cache.string(), o.resume.string());
    return kExitBadInput;
  }

  const eval::ResumePoint point = stored.resume_point();
  const std::int64_t done = generations_done(point);
  say("esc: resuming {} in {}: {} of {} generations done\n", spec->name, o.resume.string(), done,
      spec->total_generations());
  return run_everywhere(
      *spec, campaign_options(o, &point),
      [&] { return store::RunDirectory::resume(o.resume, std::move(db), stored); }, done, o.resume);
}

}  // namespace

int run_command(const RunOptions& o) {
  if (!o.resume.empty()) return resume_command(o);
  if (o.file.empty()) {
    complain("esc: error: run needs a script FILE (or --resume DIR)\n");
    return kExitUsage;
  }
  compiler::CompileResult compiled = load_script(o.file);
  if (!compiled.ok()) return kExitBadInput;
  eval::ExperimentSpec* spec = pick_experiment(compiled, o.file, o.experiment);
  if (spec == nullptr) return kExitBadInput;
  if (!apply_overrides(o, *spec)) return kExitBadInput;

  const std::filesystem::path out = o.out.empty() ? default_out(spec->name) : o.out;
  if (!prepare_dependencies(*spec, dependency_context(compiled, o, o.cache.empty() ? out / "deps" : o.cache, o.file)))
    return kExitBadInput;
  store::LaunchInfo launch;
  launch.script = std::filesystem::absolute(o.file).lexically_normal();
  launch.overrides = overrides_json(o);
  if (!spec->dependencies.empty() || spec->start_from) launch.overrides["inputs"] = inputs_hash(*spec);
  launch.software_version = ESC_VERSION_STRING;
  const auto open = [&] {
    store::RunDirectory dir(out, *spec, sources_of(compiled), launch);
    fmt::print("esc: running {} ({} controller{}, {} run{}, {}) into {}\n", spec->name,
               spec->controllers.size(), spec->controllers.size() == 1 ? "" : "s", spec->runs,
               spec->runs == 1 ? "" : "s", generations_text(*spec), out.string());
    return dir;
  };
  return run_everywhere(*spec, campaign_options(o, nullptr), open, 0, out);
}

}  // namespace esc::cli
