#include "cli/dependencies.hpp"

#include <algorithm>
#include <fstream>
#include <memory>
#include <variant>

#include <unistd.h>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "runtime/dist/mpi_session.hpp"
#include "runtime/eval/fingerprint.hpp"
#include "runtime/store/results_db.hpp"
#include "runtime/store/run_directory.hpp"

namespace esc::cli {

namespace {

constexpr int kMaxDepth = 64;

struct Prepared {
  eval::ExperimentSpec spec;          // as run, its own dependencies filled in
  store::StoredExperiment stored;     // finished
  std::filesystem::path dir;
};

bool prepare(eval::ExperimentSpec& spec, const DependencyContext& cx, int depth);

bool finished_run(const std::filesystem::path& dir) {
  try {
    return store::ResultsDb::open(dir, true).load_single().finished();
  } catch (const store::StoreError&) {
    return false;
  }
}

// Runs experiment `name` into the cache, or reuses a finished run of the same fingerprint.
std::optional<Prepared> run_or_reuse(const std::string& name, const std::string& user, const DependencyContext& cx,
                                     int depth) {
  const auto& all = cx.compiled.all_experiments;
  const auto found = std::find_if(all.begin(), all.end(), [&](const eval::ExperimentSpec& e) { return e.name == name; });
  if (found == all.end()) {
    fmt::print(stderr, "esc: error: experiment `{}` (needed by `{}`) was not compiled\n", name, user);
    return std::nullopt;
  }
  Prepared p{*found, {}, {}};
  if (!cx.apply_overrides(p.spec)) return std::nullopt;
  if (!prepare(p.spec, cx, depth + 1)) return std::nullopt;
  const std::string key = fmt::format("esc {}\n{}", cx.version, eval::fingerprint(p.spec));
  p.dir = cx.cache / fmt::format("{}-{:016x}", name, store::content_hash(key));
  // A cache entry appears only once its run has finished: the run goes into a directory of
  // its own (`.partial-PID`) and is renamed into place, so concurrent processes sharing a
  // cache never see, reuse or delete each other's unfinished runs.
  std::error_code ec;
  if (std::filesystem::exists(p.dir / "esc.db", ec) && !finished_run(p.dir)) {
    fmt::print("esc: dependency {}: {} is incomplete; running it again\n", name, p.dir.string());
    std::filesystem::remove_all(p.dir, ec);
  }
  if (std::filesystem::exists(p.dir / "esc.db", ec)) {
    fmt::print("esc: dependency {}: reused {}\n", name, p.dir.string());
  } else {
    const std::filesystem::path partial = p.dir.string() + fmt::format(".partial-{}", ::getpid());
    fmt::print("esc: dependency {}: running into {}\n", name, partial.string());
    std::filesystem::create_directories(cx.cache);
    std::filesystem::remove_all(partial, ec);
    if (cx.run_into(p.spec, partial) != kExitOk) return std::nullopt;
    std::ofstream(partial / "fingerprint.txt") << key;
    std::filesystem::rename(partial, p.dir, ec);
    if (ec) {
      // Another process finished the same run first: its result is the same; keep it.
      if (!finished_run(p.dir)) {
        fmt::print(stderr, "esc: error: cannot move {} to {}: {}\n", partial.string(), p.dir.string(), ec.message());
        return std::nullopt;
      }
      std::filesystem::remove_all(partial, ec);
    }
    fmt::print("esc: dependency {}: finished in {}\n", name, p.dir.string());
  }
  p.stored = store::ResultsDb::open(p.dir, true).load_single();
  return p;
}

const store::StoredController* stored_controller(const Prepared& p, const std::string& name) {
  const auto& cs = p.stored.controllers;
  const auto it = std::find_if(cs.begin(), cs.end(), [&](const store::StoredController& c) { return c.name == name; });
  if (it == cs.end() || it->finished.empty()) {
    fmt::print(stderr, "esc: error: {} holds no finished run of controller `{}`\n", p.dir.string(), name);
    return nullptr;
  }
  return &*it;
}

bool freeze_behaviors(eval::ExperimentSpec& spec, const eval::Dependency& dep, const Prepared& p) {
  const store::StoredController* sc = stored_controller(p, dep.controller);
  const auto ctl = std::find_if(p.spec.controllers.begin(), p.spec.controllers.end(),
                                [&](const control::ControllerSpec& c) { return c.name == dep.controller; });
  if (sc == nullptr || ctl == p.spec.controllers.end()) return false;
  const eval::RunResult* best = &sc->finished.front();
  for (const eval::RunResult& r : sc->finished)
    if (r.best_fitness > best->best_fitness) best = &r;
  auto frozen = std::make_shared<const control::ControllerSpec>(*ctl);
  if (best->best_genome.size() != frozen->genome_size()) {
    fmt::print(stderr, "esc: error: {}: the best genome of `{}` has {} genes, expected {}\n", p.dir.string(),
               dep.controller, best->best_genome.size(), frozen->genome_size());
    return false;
  }
  fmt::print("esc: dependency {}: controller {} frozen with the best genome of {} run{} (fitness {:.1f}, run {})\n",
             dep.experiment, dep.controller, sc->finished.size(), sc->finished.size() == 1 ? "" : "s",
             best->best_fitness, best->run + 1);
  for (const auto& [ci, bi] : dep.targets) {
    if (ci >= spec.controllers.size() || bi >= spec.controllers[ci].behaviors.size()) continue;
    auto* fixed = std::get_if<control::FixedController>(&spec.controllers[ci].behaviors[bi].what);
    if (fixed == nullptr) continue;
    fixed->spec = frozen;
    fixed->genome = best->best_genome;
  }
  return true;
}

bool fill_start_genomes(eval::ExperimentSpec& spec, const Prepared& p) {
  eval::StartFrom& start = *spec.start_from;
  start.genomes.clear();
  for (const control::ControllerSpec& c : spec.controllers) {
    const store::StoredController* sc = stored_controller(p, c.name);
    if (sc == nullptr) return false;
    auto& runs = start.genomes.emplace_back();
    for (const eval::RunResult& r : sc->finished) {
      if (r.best_genome.size() != c.genome_size()) {
        fmt::print(stderr, "esc: error: {}: run {} of `{}` stored {} genes, but `{}` has {} here\n", p.dir.string(),
                   r.run + 1, c.name, r.best_genome.size(), c.name, c.genome_size());
        return false;
      }
      runs.push_back(r.best_genome);
    }
  }
  fmt::print("esc: {} {} from the best genomes of {} ({} run{} each)\n", spec.name,
             start.evaluate_only ? "evaluates" : "starts", start.experiment, p.stored.runs, p.stored.runs == 1 ? "" : "s");
  return true;
}

bool prepare(eval::ExperimentSpec& spec, const DependencyContext& cx, int depth) {
  if (spec.dependencies.empty() && !spec.start_from) return true;
  if (depth > kMaxDepth) {
    fmt::print(stderr, "esc: error: dependencies of `{}` nest too deeply\n", spec.name);
    return false;
  }
  if (dist::MpiSession::current() != nullptr && dist::MpiSession::current()->active()) {
    fmt::print(stderr, "esc: error: `{}` uses the results of other experiments; run it without MPI\n", spec.name);
    return false;
  }
  // Each experiment once, however many of its controllers are used.
  for (const std::string& name : spec.needs()) {
    const auto p = run_or_reuse(name, spec.name, cx, depth);
    if (!p) return false;
    for (const eval::Dependency& dep : spec.dependencies)
      if (dep.experiment == name && !freeze_behaviors(spec, dep, *p)) return false;
    if (spec.start_from && spec.start_from->experiment == name && !fill_start_genomes(spec, *p)) return false;
  }
  return true;
}

}  // namespace

bool prepare_dependencies(eval::ExperimentSpec& spec, const DependencyContext& context) {
  return prepare(spec, context, 0);
}

}  // namespace esc::cli
