#include "runtime/store/run_directory.hpp"

#include <algorithm>
#include <bit>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "runtime/store/seed_json.hpp"
#include "runtime/store/summary_json.hpp"
#include "runtime/store/unstored_files.hpp"
#include "runtime/store/untouched_load.hpp"

namespace esc::store {

namespace fs = std::filesystem;

namespace {

constexpr const char* kCsvHeader = "generation,best,mean,sd,evaluations,steps,seconds\n";

std::string csv_line(const eval::GenerationStats& g) {
  return fmt::format("{},{:.17g},{:.17g},{:.17g},{},{},{:.3f}\n", g.generation, g.best, g.mean, g.sd, g.evaluations,
                     g.steps, g.seconds);
}

std::pair<fs::path, ResultsDb> create_new(fs::path dir, const eval::ExperimentSpec& spec,
                                          const std::vector<SourceFile>& sources, const LaunchInfo& launch) {
  const auto lock = create_output_directory(dir);
  ResultsDb db = ResultsDb::create(dir, spec, sources, launch);
  return {std::move(dir), std::move(db)};
}

}  // namespace

std::shared_ptr<const DirectoryLock> create_output_directory(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw std::runtime_error(fmt::format("cannot create `{}`: {}", dir.string(), ec.message()));
  // Locked before it is judged: a run that started into it and stored nothing yet is not
  // a directory that holds nothing.
  auto lock = DirectoryLock::acquire(dir);
  // Empty, or holding only `deps/` (the runs of the experiments whose evolved controllers
  // this one uses, written first by `esc run`) and an empty `sources/` (what an esc before
  // this one made before its database).
  bool fresh = true;
  if (fs::is_directory(dir, ec)) {
    for (const auto& entry : fs::directory_iterator(dir, ec))
      if (entry.path().filename() != kDependencyCache &&
          !(entry.path().filename() == "sources" && fs::is_empty(entry.path(), ec)))
        fresh = false;
  }
  // A run stopped before its first generation committed left nothing to lose: its files
  // (all but `deps/`) go, and the directory is used again. Only those files: anything
  // else in it (a finished run's genomes beside an emptied esc.db) keeps it.
  const std::optional<fs::path> kept = fresh ? std::nullopt : first_kept_file(dir);
  if (!fresh && !kept && holds_nothing_stored(dir)) {
    for (const auto& entry : fs::directory_iterator(dir, ec))
      if (entry.path().filename() != kDependencyCache) fs::remove_all(entry.path(), ec);
    fresh = !ec;
  }
  // Worded for every front end: `esc run --out` and esc.run's `out=` alike.
  if (!fresh)
    throw std::runtime_error(fmt::format(
        "output directory `{}` already exists and is not empty{}; results are never overwritten: "
        "choose another output directory or remove it", dir.string(),
        kept ? fmt::format(" (it holds {})", kept->lexically_relative(dir).generic_string()) : ""));
  return lock;
}

nlohmann::ordered_json write_sources(const fs::path& dir, const std::vector<SourceFile>& sources) {
  // Made after esc.db: a directory holding sources/ holds a database that says what it is.
  std::error_code ec;
  fs::create_directories(dir / "sources", ec);
  if (ec) throw std::runtime_error(fmt::format("cannot create `{}`: {}", (dir / "sources").string(), ec.message()));
  nlohmann::ordered_json files = nlohmann::ordered_json::array();
  for (const SourceFile& s : sources) {
    const std::string flat = fmt::format("{:02}-{}", files.size(), s.name.filename().string());
    write_atomically(dir / "sources" / flat, s.text);
    files.push_back({{"name", s.name.generic_string()}, {"stored_as", "sources/" + flat}});
  }
  return files;
}

nlohmann::ordered_json settings_json(const eval::ExperimentSpec& spec, const std::vector<SourceFile>& sources,
                                     const nlohmann::ordered_json& files) {
  return {{"experiment", spec.name},
          {"seed", seed_json(spec.seed)},
          {"content_hash", campaign_hash(spec.name, sources)},
          {"sources", files},
          {"settings", nlohmann::ordered_json(spec.resolved_settings)}};
}

std::uint64_t content_hash(std::string_view text, std::uint64_t h) noexcept {
  for (unsigned char ch : text) {
    h ^= ch;
    h *= 0x100000001b3ULL;
  }
  return h;
}

std::string genome_checksum(std::string_view controller, int run, const std::vector<double>& genome, double fitness,
                            std::uint64_t evaluation_seed, std::string_view tree) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  const auto word = [&h](std::uint64_t w) {   // little-endian whatever the machine
    char bytes[8];
    for (int i = 0; i < 8; ++i) bytes[i] = static_cast<char>((w >> (8 * i)) & 0xff);
    h = content_hash(std::string_view(bytes, 8), h);
  };
  const auto text = [&](std::string_view t) {
    word(t.size());
    h = content_hash(t, h);
  };
  text(controller);
  word(static_cast<std::uint64_t>(run));
  word(std::bit_cast<std::uint64_t>(fitness));
  word(evaluation_seed);
  word(genome.size());
  for (const double g : genome) word(std::bit_cast<std::uint64_t>(g));
  text(tree);
  return fmt::format("{:016x}", h);
}

void write_atomically(const fs::path& file, std::string_view text) {
  const fs::path tmp = fs::path(file).concat(".tmp");
  bool written = false;
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << text;
    out.flush();
    out.close();
    written = !out.fail();
  }
  // A partial file (a full disk) is not left behind: the old file, if any, is as it was.
  std::error_code ec;
  if (!written) {
    fs::remove(tmp, ec);
    throw std::runtime_error(fmt::format("cannot write {}", file.string()));
  }
  fs::rename(tmp, file);
}

std::string best_tree_script(const std::string& controller, const std::string& architecture,
                             const eval::RunResult& run) {
  std::string s = fmt::format("// The best tree of controller {} ({}), run {}: fitness {:.17g}\n"
                              "// (generation {}, individual {}, run seed {}).\n",
                              controller, architecture, run.run + 1, run.best_fitness, run.best_generation,
                              run.best_index, run.seed);
  if (run.best_behavior != run.best_tree)
    s += "// The tree chooses among its controller's actions or behaviors at each step:\n// " + run.best_tree + "\n";
  if (run.best_behavior.empty()) return s;
  if (run.best_behavior != run.best_tree) s += "// As a behavior, its actions' wheel commands inlined:\n";
  return s + fmt::format("behavior {}_run{:02}() {{ {} }}\n", controller, run.run + 1, run.best_behavior);
}

std::string generations_csv(const std::vector<eval::GenerationStats>& generations) {
  std::string s = kCsvHeader;
  for (const auto& g : generations) s += csv_line(g);
  return s;
}

RunDirectory::RunDirectory(fs::path dir, ResultsDb db) : dir_(std::move(dir)), db_(std::move(db)) {}

RunDirectory::RunDirectory(std::pair<fs::path, ResultsDb> created)
    : RunDirectory(std::move(created.first), std::move(created.second)) {}

RunDirectory::RunDirectory(fs::path dir, const eval::ExperimentSpec& spec, const std::vector<SourceFile>& sources,
                           const LaunchInfo& launch)
    : RunDirectory(create_new(std::move(dir), spec, sources, launch)) {
  write_atomically(dir_ / "settings.json", settings_json(spec, sources, write_sources(dir_, sources)).dump(2) + "\n");
  partial_ = eval::campaign_result_of(spec);
  for (const control::ControllerSpec& c : spec.controllers) controllers_.emplace_back(c.name, spec.genome_size_of(c));
  write_summary();
}

RunDirectory RunDirectory::resume(fs::path dir, ResultsDb db, const StoredExperiment& stored,
                                  const eval::ResumePoint& point, SummarySink summary) {
  RunDirectory rd(std::move(dir), std::move(db));
  rd.summary_ = std::move(summary);
  rd.partial_ = stored.result();
  // Runs carried on are not finished any more: summary.json shows them when they are again.
  for (eval::ControllerResult& c : rd.partial_.controllers)
    std::erase_if(c.runs, [&](const eval::RunResult& r) {
      return std::any_of(point.in_progress.begin(), point.in_progress.end(),
                         [&](const auto& p) { return p.controller == c.name && p.state.run == r.run; });
    });
  std::erase_if(rd.partial_.controllers, [](const eval::ControllerResult& c) { return c.runs.empty(); });
  for (const StoredController& c : stored.controllers) rd.controllers_.emplace_back(c.name, c.genome_size);
  for (const StoredController& c : stored.controllers) {
    if (c.finished.empty() && c.in_progress.empty()) continue;
    fs::create_directories(rd.dir_ / c.name);
    for (const auto& r : c.finished) {
      write_atomically(rd.run_file(c.name, r.run, ".csv"), generations_csv(r.generations));
      rd.write_best(c.name, c.architecture, r);
    }
    for (const auto& s : c.in_progress)
      write_atomically(rd.run_file(c.name, s.run, ".csv"), generations_csv(s.generations));
  }
  rd.write_summary();
  return rd;
}

void RunDirectory::carry_on(const fs::path& dir, ResultsDb& db, const eval::ExperimentSpec& spec,
                            const nlohmann::ordered_json& overrides) {
  db.extend({{db.experiment_id(), &spec, overrides}});
  rewrite_settings(dir, spec);
}

void RunDirectory::rewrite_settings(const fs::path& dir, const eval::ExperimentSpec& spec) {
  const fs::path file = dir / "settings.json";
  std::ifstream in(file);
  nlohmann::ordered_json doc = nlohmann::ordered_json::parse(in, nullptr, false);
  if (doc.is_discarded() || !doc.is_object()) return;   // a view of the database; it stays as it was
  doc["settings"] = nlohmann::ordered_json(spec.resolved_settings);
  write_atomically(file, doc.dump(2) + "\n");
}

fs::path RunDirectory::run_file(const std::string& controller, int run, std::string_view ext) const {
  return dir_ / controller / fmt::format("run-{:02}{}", run + 1, ext);
}

void RunDirectory::generation_done(const control::ControllerSpec& controller, int run,
                                   const eval::GenerationStats& g) {
  const std::string key = fmt::format("{}/{}", controller.name, run);
  const fs::path file = run_file(controller.name, run, ".csv");
  if (key != csv_key_) {
    fs::create_directories(dir_ / controller.name);
    // A run continued after a resume appends to the CSV rewritten from the database.
    const bool resumed = g.generation > 0 && fs::exists(file);
    csv_ = std::ofstream(file, resumed ? std::ios::app : std::ios::trunc);
    if (!resumed) csv_ << kCsvHeader;
    csv_key_ = key;
  }
  csv_ << csv_line(g);
  csv_.flush();
  if (!csv_) throw std::runtime_error(fmt::format("cannot write {}", file.string()));
}

void RunDirectory::checkpoint(const control::ControllerSpec& controller, const eval::RunState& state) {
  db_.commit_generation(controller.name, state);
}

void RunDirectory::best_traced(const control::ControllerSpec& controller, const eval::RunResult& run,
                               std::span<const eval::TraceStep> trace) {
  db_.commit_replay(controller.name, run, trace);
}

void RunDirectory::write_best(const std::string& controller, const std::string& architecture,
                              const eval::RunResult& run) {
  const std::uint64_t evaluation_seed =
      eval::evaluation_seed(run.seed, run.best_generation, static_cast<std::size_t>(run.best_index));
  nlohmann::ordered_json best = {{"controller", controller},
                                 {"architecture", architecture},
                                 {"run", run.run + 1},
                                 {"seed", seed_json(run.seed)},
                                 {"fitness", run.best_fitness},
                                 // Where the best evaluation happened, which fixes its seed: `esc replay`
                                 // re-simulates it from this file alone.
                                 {"generation", run.best_generation},
                                 {"individual", run.best_index},
                                 {"evaluation_seed", seed_json(evaluation_seed)},
                                 {"genome", run.best_genome}};
  if (!run.best_tree.empty()) best["tree"] = run.best_tree;
  // The genome holds a network per role, one after the other (docs/groups.md, "Roles").
  if (partial_.roles > 1) best["roles"] = partial_.roles;
  best["checksum"] = genome_checksum(controller, run.run + 1, run.best_genome, run.best_fitness, evaluation_seed,
                                     run.best_tree);
  write_atomically(run_file(controller, run.run, ".best.json"), best.dump(1) + "\n");
  if (!run.best_tree.empty())
    write_atomically(run_file(controller, run.run, ".best.esc"), best_tree_script(controller, architecture, run));
}

void RunDirectory::run_done(const control::ControllerSpec& controller, const eval::RunResult& run) {
  db_.commit_run(controller.name, run);
  fs::create_directories(dir_ / controller.name);
  write_best(controller.name, controller.architecture(), run);
  // Runs that advance together finish in any order: each goes to its controller, in run
  // order, and controllers stay in the experiment's order.
  const auto rank = [&](const std::string& name) {
    return std::find_if(controllers_.begin(), controllers_.end(), [&](const auto& c) { return c.first == name; }) -
           controllers_.begin();
  };
  auto& cs = partial_.controllers;
  auto c = std::find_if(cs.begin(), cs.end(),
                        [&](const eval::ControllerResult& r) { return rank(r.name) >= rank(controller.name); });
  if (c == cs.end() || c->name != controller.name) {
    const auto size = controllers_.at(static_cast<std::size_t>(rank(controller.name))).second;
    c = cs.insert(c, {controller.name, controller.architecture(), size, {}, controller.choice_names()});
  }
  const auto at = std::find_if(c->runs.begin(), c->runs.end(), [&](const eval::RunResult& r) { return r.run > run.run; });
  c->runs.insert(at, run);
  write_summary();
}

void RunDirectory::finish(const eval::CampaignResult& result) {
  db_.mark_finished();
  partial_ = result;
  write_summary();
}

void RunDirectory::write_summary() {
  if (summary_) summary_(partial_);
  else write_atomically(dir_ / "summary.json", summary_text(summary_json(partial_)));
}

}  // namespace esc::store
