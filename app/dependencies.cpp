#include "app/dependencies.hpp"

#include <algorithm>
#include <bit>
#include <fstream>
#include <iterator>
#include <memory>
#include <system_error>
#include <variant>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/error.hpp"
#include "app/partial_run.hpp"
#include "app/ranks.hpp"
#include "compiler/setting_keys.hpp"
#include "runtime/eval/fingerprint.hpp"
#include "runtime/eval/genome_fit.hpp"
#include "runtime/store/results_db.hpp"
#include "runtime/store/run_directory.hpp"

namespace esc::app {

namespace {

constexpr int kMaxDepth = 64;

struct Prepared {
  eval::ExperimentSpec spec;          // as run, its own dependencies filled in
  store::StoredExperiment stored;     // finished
  std::filesystem::path dir;
};

void prepare(eval::ExperimentSpec& spec, const DependencyContext& cx, int depth);

// Under MPI every rank prepares the same dependencies in the same order (running one is a
// collective); rank 0 alone reads and writes the cache, tells the others what it decided
// (reuse or run) and sends them what it read, and alone reports.
template <typename... Args>
void tell(const DependencyContext& cx, fmt::format_string<Args...> format, Args&&... args) {
  if (!follower_rank()) cx.events.note({Note::Kind::Dependency, fmt::format(format, std::forward<Args>(args)...)});
}

// Rank 0's refusal, `message`, on every rank (empty: none).
void agree_or_throw(std::string message) {
  const bool refused = agree(!message.empty());
  if (!refused) return;
  if (follower_rank()) throw follower_error(ErrorKind::Dependency);
  throw Error(ErrorKind::Dependency, std::move(message));
}

// What dependents read of a finished run (its controllers' architectures and finished runs'
// best genomes), from rank 0
// to the others. Doubles travel as their bits, so every rank holds the same genomes.
std::string pack(const store::StoredExperiment& stored) {
  nlohmann::json j = {{"runs", stored.runs}, {"controllers", nlohmann::json::array()}};
  for (const store::StoredController& c : stored.controllers) {
    nlohmann::json runs = nlohmann::json::array();
    for (const eval::RunResult& r : c.finished) {
      std::vector<std::uint64_t> genome;
      for (const double g : r.best_genome) genome.push_back(std::bit_cast<std::uint64_t>(g));
      runs.push_back({{"run", r.run}, {"best_fitness", std::bit_cast<std::uint64_t>(r.best_fitness)},
                      {"best_genome", genome}});
    }
    j["controllers"].push_back({{"name", c.name}, {"architecture", c.architecture}, {"finished", runs}});
  }
  return j.dump();
}

store::StoredExperiment unpack(const std::string& text) {
  const nlohmann::json j = nlohmann::json::parse(text);
  store::StoredExperiment stored;
  stored.runs = j["runs"].get<int>();
  for (const nlohmann::json& c : j["controllers"]) {
    store::StoredController& sc = stored.controllers.emplace_back();
    sc.name = c["name"].get<std::string>();
    sc.architecture = c["architecture"].get<std::string>();
    for (const nlohmann::json& r : c["finished"]) {
      eval::RunResult& result = sc.finished.emplace_back();
      result.run = r["run"].get<int>();
      result.best_fitness = std::bit_cast<double>(r["best_fitness"].get<std::uint64_t>());
      for (const std::uint64_t g : r["best_genome"].get<std::vector<std::uint64_t>>())
        result.best_genome.push_back(std::bit_cast<double>(g));
    }
  }
  return stored;
}

// Rank 0 loads the finished run in `dir`; every rank returns what it holds.
store::StoredExperiment load_finished(const std::filesystem::path& dir) {
  std::string text, error;
  if (!follower_rank()) {
    try {
      text = pack(store::ResultsDb::open(dir, true).load_single());
    } catch (const store::StoreError& e) {
      error = e.what();
    }
  }
  agree_or_throw(std::move(error));
  agree(text);
  return unpack(text);
}

bool finished_run(const std::filesystem::path& dir) {
  try {
    return store::ResultsDb::open(dir, true).load_single().finished();
  } catch (const store::StoreError&) {
    return false;
  }
}

// Whether cache entry `dir` was made for `key`: the whole fingerprint stored with it, not
// only the hash its name holds.
bool same_fingerprint(const std::filesystem::path& dir, const std::string& key) {
  std::ifstream in(dir / kFingerprintFile, std::ios::binary);
  const std::string stored{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  return in.is_open() && stored == key;
}

Prepared load_into(Prepared& p) {
  p.stored = load_finished(p.dir);
  return std::move(p);
}

// Moves a finished run from `partial` into its cache entry and loads what dependents read
// of it.
Prepared finish_dependency(const DependencyContext& cx, const std::string& name, const std::string& key,
                           const std::filesystem::path& partial, Prepared& p) {
  std::error_code ec;
  std::string error;
  if (!follower_rank()) {
    std::ofstream(partial / kFingerprintFile) << key;
    std::filesystem::rename(partial, p.dir, ec);
    if (ec) {
      // Another process finished the same run first: its result is the same; keep it.
      if (!finished_run(p.dir))
        error = fmt::format("cannot move {} to {}: {}", partial.string(), p.dir.string(), ec.message());
      else
        std::filesystem::remove_all(partial, ec);
    }
  }
  agree_or_throw(std::move(error));
  tell(cx, "dependency {}: finished in {}", name, p.dir.string());
  return load_into(p);
}

// Whether the genomes `dependency` stores can serve `user` as it uses them, refused before the
// dependency runs: a genome holds one network per role, so a start or an evaluation needs as
// many roles, and a frozen behavior (one network) an experiment of one role.
void check_roles(const eval::ExperimentSpec& user, const eval::ExperimentSpec& dependency) {
  if (user.start_from && user.start_from->experiment == dependency.name && dependency.roles != user.roles)
    throw Error(ErrorKind::Dependency,
                fmt::format("`{}` evolves {} role{} in one genome and `{}` has {}: a genome holds one network per "
                            "role, so both need the same roles (the group's size may differ)",
                            dependency.name, dependency.roles, dependency.roles == 1 ? "" : "s", user.name,
                            user.roles));
  for (const eval::Dependency& dep : user.dependencies)
    if (dep.experiment == dependency.name && dependency.roles > 1)
      throw Error(ErrorKind::Dependency,
                  fmt::format("`{}` evolves {} roles of `{}` in one genome, and a behavior of `{}` is one network: "
                              "freeze a controller of an experiment with one role (`--set roles` applies to "
                              "dependencies too)",
                              dependency.name, dependency.roles, dep.controller, user.name));
}

// Runs experiment `name` into the cache, or reuses a finished run of the same fingerprint.
Prepared run_or_reuse(const std::string& name, const eval::ExperimentSpec& user, const DependencyContext& cx,
                      int depth) {
  const auto& all = cx.compiled.all_experiments;
  const auto found = std::find_if(all.begin(), all.end(), [&](const eval::ExperimentSpec& e) { return e.name == name; });
  if (found == all.end())
    throw Error(ErrorKind::Dependency, fmt::format("experiment `{}` (needed by `{}`) was not compiled", name, user.name));
  Prepared p{*found, {}, {}};
  // The script's settings before the command line's, as for the experiment run itself.
  apply_dependency_settings(p.spec, user.dependency_settings, user.name);
  cx.apply_overrides(p.spec);
  check_roles(user, p.spec);
  prepare(p.spec, cx, depth + 1);
  const std::string key = fmt::format("esc {}\n{}", cx.version, eval::fingerprint(p.spec));
  p.dir = cx.cache / fmt::format("{}-{:016x}", name, store::content_hash(key));
  // A cache entry appears only once its run has finished: the run goes into a directory of
  // its own (partial_run.hpp) and is renamed into place, so concurrent processes sharing a
  // cache never see, reuse or delete each other's unfinished runs; one whose process is
  // gone is continued.
  // Rank 0 decides whether to reuse, holding the cache's lock until the entry is prepared:
  // of the processes that need it at once, one runs it and the others then reuse it. The
  // other ranks follow.
  std::error_code ec;
  bool reuse = false;
  std::string refused;
  std::optional<CacheLock> cache_lock;
  if (!follower_rank() && !cx.reuse_only) {   // reading what a run used locks nothing
    std::filesystem::create_directories(cx.cache, ec);
    try {
      cache_lock.emplace(CacheLock::acquire(cx.cache, [&] {
        tell(cx, "dependency {}: another process is preparing a dependency in {}; waiting for it", name,
             cx.cache.string());
      }));
    } catch (const std::system_error& e) {
      refused = fmt::format("cannot create the dependency cache {}: {}", cx.cache.string(), e.what());
    }
  }
  if (!follower_rank() && refused.empty()) {
    if (std::filesystem::exists(p.dir / "esc.db", ec)) {
      const auto incomplete = [&] {
        tell(cx, "dependency {}: {} is incomplete; running it again", name, p.dir.string());
        std::filesystem::remove_all(p.dir, ec);
      };
      try {
        if (!store::ResultsDb::open(p.dir, true).load_single().finished()) incomplete();
      } catch (const store::NothingStored&) {
        incomplete();
      } catch (const store::StoreError& e) {
        // Damaged: never used, and not removed either (what damaged it may matter).
        refused = fmt::format("dependency {}: {}; remove it to run it again", name, e.what());
      }
    }
    reuse = refused.empty() && std::filesystem::exists(p.dir / "esc.db", ec);
    if (reuse && !same_fingerprint(p.dir, key))
      refused = fmt::format("{} is not the run experiment `{}` needs: its fingerprint.txt differs from this run's "
                            "inputs (its name holds only their hash); remove it or give another --cache",
                            p.dir.string(), name);
  }
  agree_or_throw(std::move(refused));
  if (agree(reuse)) {
    tell(cx, "dependency {}: reused {}", name, p.dir.string());
    return load_into(p);
  }
  if (cx.reuse_only)
    throw Error(ErrorKind::Dependency, fmt::format("experiment `{}` (needed by `{}`) has no finished run in {}; run it "
                                                   "first (esc run)",
                                                   name, user.name, cx.cache.string()));
  // Rank 0 names the run's directory and holds its lock; the other ranks only follow.
  std::optional<PartialRun> mine;
  std::string no_cache;
  if (!follower_rank()) {
    std::filesystem::create_directories(cx.cache, ec);
    try {
      mine.emplace(PartialRun::create(p.dir));
    } catch (const std::system_error& e) {
      no_cache = fmt::format("cannot create the dependency cache {}: {}", cx.cache.string(), e.what());
    }
  }
  agree_or_throw(std::move(no_cache));
  const std::filesystem::path partial = mine ? mine->dir() : std::filesystem::path();
  // Under MPI the other ranks would have to read the abandoned run: it starts again.
  if (job() == nullptr) {
    if (const auto abandoned = take_over_abandoned(p.dir, *mine)) {
      tell(cx, "dependency {}: continuing the run a stopped process left in {}", name, abandoned->string());
      if (cx.resume_into(p.spec, partial)) return finish_dependency(cx, name, key, partial, p);
      tell(cx, "dependency {}: running it again", name);
    }
  }
  tell(cx, "dependency {}: running into {}", name, partial.string());
  if (!follower_rank()) std::filesystem::remove_all(partial, ec);
  cx.run_into(p.spec, partial);
  return finish_dependency(cx, name, key, partial, p);
}

const store::StoredController& stored_controller(const Prepared& p, const std::string& name) {
  const auto& cs = p.stored.controllers;
  const auto it = std::find_if(cs.begin(), cs.end(), [&](const store::StoredController& c) { return c.name == name; });
  if (it == cs.end() || it->finished.empty())
    throw Error(ErrorKind::Dependency, fmt::format("{} holds no finished run of controller `{}`", p.dir.string(), name));
  return *it;
}

void freeze_behaviors(const DependencyContext& cx, eval::ExperimentSpec& spec, const eval::Dependency& dep,
                      const Prepared& p) {
  const store::StoredController* sc = &stored_controller(p, dep.controller);
  const auto ctl = std::find_if(p.spec.controllers.begin(), p.spec.controllers.end(),
                                [&](const control::ControllerSpec& c) { return c.name == dep.controller; });
  if (ctl == p.spec.controllers.end())
    throw Error(ErrorKind::Dependency, fmt::format("experiment `{}` compares no controller `{}`", p.spec.name, dep.controller));
  const eval::RunResult* best = &sc->finished.front();
  for (const eval::RunResult& r : sc->finished)
    if (r.best_fitness > best->best_fitness) best = &r;
  auto frozen = std::make_shared<const control::ControllerSpec>(*ctl);
  if (const std::string why = eval::genome_problem(*frozen, best->best_genome); !why.empty())
    throw Error(ErrorKind::Dependency,
                fmt::format("{}: the best genome of `{}` cannot be frozen: {}", p.dir.string(), dep.controller, why));
  tell(cx, "dependency {}: controller {} frozen with the best genome of {} run{} (fitness {:.1f}, run {})",
             dep.experiment, dep.controller, sc->finished.size(), sc->finished.size() == 1 ? "" : "s",
             best->best_fitness, best->run + 1);
  for (const auto& [ci, bi] : dep.targets) {
    if (ci >= spec.controllers.size() || bi >= spec.controllers[ci].behaviors.size()) continue;
    auto* fixed = std::get_if<control::FixedController>(&spec.controllers[ci].behaviors[bi].what);
    if (fixed == nullptr) continue;
    fixed->spec = frozen;
    fixed->genome = best->best_genome;
  }
}

void fill_start_genomes(const DependencyContext& cx, eval::ExperimentSpec& spec, const Prepared& p) {
  eval::StartFrom& start = *spec.start_from;
  start.genomes.clear();
  for (const control::ControllerSpec& c : spec.controllers) {
    const store::StoredController& sc = stored_controller(p, c.name);
    auto& runs = start.genomes.emplace_back();
    for (const eval::RunResult& r : sc.finished) {
      if (const std::string why = eval::genome_problem(c, r.best_genome, spec.roles, sc.architecture); !why.empty())
        throw Error(ErrorKind::Dependency, fmt::format("{}: the best genome of run {} of `{}` cannot start a run here: {}",
                                                       p.dir.string(), r.run + 1, c.name, why));
      runs.push_back({r.run, r.best_fitness, r.best_genome});
    }
  }
  tell(cx, "{} {} from the best genomes of {} ({} run{} each)", spec.name,
             start.evaluate_only ? "evaluates" : "starts", start.experiment, p.stored.runs, p.stored.runs == 1 ? "" : "s");
}

void prepare(eval::ExperimentSpec& spec, const DependencyContext& cx, int depth) {
  if (spec.dependencies.empty() && !spec.start_from) return;
  if (depth > kMaxDepth)
    throw Error(ErrorKind::Dependency, fmt::format("dependencies of `{}` nest too deeply", spec.name));
  // Each experiment once, however many of its controllers are used.
  for (const std::string& name : spec.needs()) {
    const Prepared p = run_or_reuse(name, spec, cx, depth);
    for (const eval::Dependency& dep : spec.dependencies)
      if (dep.experiment == name) freeze_behaviors(cx, spec, dep, p);
    if (spec.start_from && spec.start_from->experiment == name) fill_start_genomes(cx, spec, p);
  }
}

}  // namespace

void apply_dependency_settings(eval::ExperimentSpec& spec, const std::vector<eval::DependencySetting>& given,
                               const std::string& user) {
  std::vector<std::pair<std::string, std::string>> own;
  bool further = false;
  for (const eval::DependencySetting& s : given) {
    if (s.path.empty() || s.path.front() != spec.name) continue;
    if (s.path.size() == 1) {
      own.emplace_back(s.key, s.value);
    } else {
      spec.dependency_settings.push_back({{s.path.begin() + 1, s.path.end()}, s.key, s.value});
      further = true;
    }
  }
  if (!own.empty()) {
    // Together, as the compiler checked them.
    if (const std::string error = compiler::apply_settings(spec, own); !error.empty())
      throw Error(ErrorKind::Setting, fmt::format("experiment {}, as {} needs it: {}", spec.name, user, error));
  }
  if (further) compiler::resolve_settings(spec);
}

void prepare_dependencies(eval::ExperimentSpec& spec, const DependencyContext& context) {
  prepare(spec, context, 0);
}

bool is_cache_entry(const std::filesystem::path& dir) {
  std::error_code ec;
  return std::filesystem::exists(dir / kFingerprintFile, ec);
}

std::filesystem::path cache_of_run(const std::filesystem::path& dir) {
  return is_cache_entry(dir) ? dir.parent_path() : dir / store::kDependencyCache;
}

}  // namespace esc::cli
