// `esc replay`: re-simulates stored controllers through the evaluator (the same code path,
// seed and settings as the run, so a replay of the stored best evaluation is bit-identical
// to the one in esc.db) and writes what a paper or a slide can use: an SVG of the
// trajectories and a CSV of every step (runtime/report/trajectory_*.hpp), and on request an
// animation (cli/replay_animation.hpp).
#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/output_files.hpp"
#include "app/results.hpp"
#include "app/store_errors.hpp"
#include "app/stored_run.hpp"
#include "cli/commands.hpp"
#include "cli/load.hpp"
#include "cli/replay_animation.hpp"
#include "cli/replay_evaluations.hpp"
#include "cli/table_text.hpp"
#include "cli/terminal_events.hpp"
#include "compiler/names.hpp"
#include "runtime/eval/campaign.hpp"
#include "runtime/report/trajectory_csv.hpp"
#include "runtime/report/trajectory_svg.hpp"

namespace esc::cli {

namespace {

namespace fs = std::filesystem;

// One stored evaluation to replay: a controller's genome and the seed of its evaluation.
struct Subject {
  std::string controller;
  int run = 0;                                // from 0
  std::uint64_t run_seed = 0;
  std::vector<double> genome;
  std::uint64_t seed = 0;
  std::optional<double> fitness;              // as stored, to check against
  const store::StoredReplay* stored = nullptr;   // the same evaluation stored in esc.db, if it is
  std::string member;                         // "cell 17": a member of the final front or archive
  std::optional<double> member_fitness;       // as stored in its own evaluation
  // A member's descriptors as stored, to check against where its own evaluation is known.
  std::vector<double> member_descriptors;
};

struct Collect final : eval::TraceSink {
  std::vector<eval::TraceStep> steps;
  void on_step(const eval::TraceStep& t) override { steps.push_back(t); }
};

// "1,3-5" (epochs from 1) as indices from 0, in order; nullopt after printing an error.
std::optional<std::vector<int>> parse_epochs(const std::string& list, int epochs) {
  std::vector<int> chosen;
  if (list.empty()) {
    for (int e = 0; e < epochs; ++e) chosen.push_back(e);
    return chosen;
  }
  std::size_t at = 0;
  while (at <= list.size()) {
    const std::size_t comma = std::min(list.find(',', at), list.size());
    const std::string item = list.substr(at, comma - at);
    const std::size_t dash = item.find('-');
    char* end = nullptr;
    const long first = std::strtol(item.c_str(), &end, 10);
    bool ok = end != item.c_str() && (dash == std::string::npos ? *end == '\0' : end == item.c_str() + dash);
    long last = first;
    if (ok && dash != std::string::npos) {
      const char* from = item.c_str() + dash + 1;
      last = static_cast<int>(std::strtol(from, &end, 10));
      ok = end != from && *end == '\0';
    }
    if (!ok || first < 1 || last < first || last > epochs) {
      complain("esc: error: --epochs {}: `{}` is not an epoch or a range of epochs between 1 and {} (e.g. 1,3-5)\n",
               list, item, epochs);
      return std::nullopt;
    }
    for (auto e = static_cast<int>(first); e <= last; ++e)
      if (std::find(chosen.begin(), chosen.end(), e - 1) == chosen.end()) chosen.push_back(e - 1);
    at = comma + 1;
  }
  std::sort(chosen.begin(), chosen.end());
  return chosen;
}

// The run to replay of a stored controller: --run, else the run whose best evaluation is
// stored as the controller's replay, else its best run. Null after printing an error.
const eval::RunResult* pick_run(const store::StoredController& c, const std::optional<int>& run) {
  const auto& runs = c.finished;
  if (run) {
    const auto it = std::find_if(runs.begin(), runs.end(), [&](const eval::RunResult& r) { return r.run + 1 == *run; });
    if (it != runs.end()) return &*it;
    complain("esc: error: controller {} has no finished run {} ({} finished)\n", c.name, *run, runs.size());
    return nullptr;
  }
  if (runs.empty()) {
    complain("esc: error: controller {} has no finished run to replay\n", c.name);
    return nullptr;
  }
  if (c.replay)
    for (const eval::RunResult& r : runs)
      if (r.run == c.replay->run) return &r;
  return &*std::max_element(runs.begin(), runs.end(), [](const eval::RunResult& a, const eval::RunResult& b) {
    return a.best_fitness < b.best_fitness;
  });
}

std::vector<Subject> stored_subjects(const store::StoredExperiment& stored, const ReplayOptions& o) {
  std::vector<Subject> subjects;
  std::vector<std::string> names;
  for (const store::StoredController& c : stored.controllers) {
    names.push_back(c.name);
    if (!o.controller.empty() && c.name != o.controller) continue;
    const eval::RunResult* r = pick_run(c, o.run);
    if (r == nullptr) return {};
    Subject s{c.name, r->run, r->seed, r->best_genome,
              eval::evaluation_seed(r->seed, r->best_generation, static_cast<std::size_t>(r->best_index)),
              r->best_fitness, nullptr, {}, {}, {}};
    if (c.replay && c.replay->run == r->run && c.replay->seed == s.seed) s.stored = &*c.replay;
    subjects.push_back(std::move(s));
  }
  if (subjects.empty()) {
    complain("esc: error: the run has no controller `{}`; it compares {}\n", o.controller,
             compiler::quoted_list(names, " and "));
    if (const auto near = compiler::closest(o.controller, names)) complain("help: did you mean `{}`?\n", *near);
  }
  return subjects;
}

// Makes `s` the member `member` of its run's final front or archive. False after printing
// an error.
bool pick_member(Subject& s, const evo::Members& kept, std::int64_t member) {
  const bool front = kept.kind == evo::MemberKind::Front;
  const auto it = std::find_if(kept.members.begin(), kept.members.end(),
                               [&](const evo::Member& m) { return m.cell == member; });
  if (it == kept.members.end() || it->genome.empty()) {
    const std::optional<std::size_t> cells = kept.cells();
    if (!front && cells && (member < 0 || static_cast<std::size_t>(member) >= *cells))
      complain("esc: error: {} run {}'s archive has no cell {}: its cells are numbered 0-{}\n", s.controller,
               s.run + 1, member, *cells - 1);
    else if (!front && it == kept.members.end())
      complain("esc: error: cell {} of {} run {}'s archive is empty ({} cells filled; esc export --table archive "
               "lists them)\n", member, s.controller, s.run + 1, kept.members.size());
    else if (it == kept.members.end())
      complain("esc: error: {} run {}'s final front has {} members, numbered from 0; {} is not one\n", s.controller,
               s.run + 1, kept.members.size(), member);
    else
      complain("esc: error: {} run {}'s archive keeps behaviors, not the genomes that produced them: there is "
               "nothing to replay in cell {}\n", s.controller, s.run + 1, member);
    return false;
  }
  s.genome = it->genome;
  s.member = fmt::format("{} {}", front ? "member" : "cell", member);
  s.fitness.reset();
  s.stored = nullptr;
  // The fitness follows the objectives the optimizer computes itself (novelty).
  if (kept.own_objectives.size() < it->objectives.size()) s.member_fitness = it->objectives[kept.own_objectives.size()];
  // Its own evaluation, where the state says which it was; a state saved before origins were
  // kept leaves the run's best's seed, exact wherever evaluations draw nothing.
  if (it->measured.known()) {
    s.seed = eval::evaluation_seed_of(s.run_seed, it->measured);
    s.fitness = s.member_fitness;
    s.member_fitness.reset();
    s.member_descriptors = it->descriptors;
  }
  return true;
}

// A genome file written by `esc run` (CONTROLLER/run-NN.best.json). Nullopt after printing.
std::optional<Subject> genome_subject(const fs::path& file, const ReplayOptions& o) {
  std::ifstream in(file);
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
    Subject s;
    s.controller = j.at("controller").get<std::string>();
    s.run = j.at("run").get<int>() - 1;
    s.genome = j.at("genome").get<std::vector<double>>();
    s.fitness = j.at("fitness").get<double>();
    if (!app::genome_file_intact(j)) {
      complain("esc: error: {} is damaged: its genome, fitness or seed does not match its checksum\n", file.string());
      return std::nullopt;
    }
    if (o.seed) s.seed = *o.seed;
    else if (const std::optional<std::uint64_t> seed = app::genome_file_seed(j)) s.seed = *seed;
    else {
      complain("esc: error: {} does not say its evaluation's seed (written by an older esc): give --seed\n",
               file.string());
      return std::nullopt;
    }
    return s;
  } catch (const std::exception& e) {   // JSON errors, a seed that is not one
    complain("esc: error: {} is not a genome file of esc run ({})\n", file.string(), e.what());
    return std::nullopt;
  }
}

// The first difference between a replay and the stored one, or empty when bit-identical.
std::string first_difference(std::span<const eval::TraceStep> now, const store::StoredReplay& stored) {
  if (now.size() != stored.steps.size())
    return fmt::format("{} steps instead of the stored {}", now.size(), stored.steps.size());
  for (std::size_t i = 0; i < now.size(); ++i) {
    const eval::TraceStep& a = now[i];
    const eval::TraceStep& b = stored.steps[i];
    // An older esc stored each epoch's last step before the epoch's end terms were counted.
    const bool epoch_end = i + 1 == now.size() || now[i + 1].epoch != a.epoch;
    const bool fitness = a.fitness == b.fitness || (epoch_end && !stored.end_terms_counted);
    const bool same = a.epoch == b.epoch && a.step == b.step && a.pose.x_m == b.pose.x_m && a.pose.y_m == b.pose.y_m &&
                      a.pose.heading_rad == b.pose.heading_rad && a.ir == b.ir && a.left_command == b.left_command &&
                      a.right_command == b.right_command && a.left_speed_mps == b.left_speed_mps &&
                      a.right_speed_mps == b.right_speed_mps && a.action == b.action && fitness &&
                      a.collided == b.collided && a.energy == b.energy;
    if (!same) return fmt::format("it differs from the stored replay at epoch {}, step {}", a.epoch + 1, a.step + 1);
  }
  return {};
}

std::string epochs_text(const std::vector<int>& epochs, int total) {
  if (total == 1) return "its one epoch";
  if (static_cast<int>(epochs.size()) == total) return fmt::format("all {} epochs", total);
  std::string s;
  for (const int e : epochs) s += fmt::format("{}{}", s.empty() ? "" : ",", e + 1);
  return fmt::format("epoch{} {} of {}", epochs.size() == 1 ? "" : "s", s, total);
}

// Replays one subject in `spec` and writes its files. Returns the exit status.
int replay_one(const eval::ExperimentSpec& spec, const Subject& s, const ReplayOptions& o, const std::vector<int>& epochs,
               const fs::path& out) {
  const bool faithful = o.script.empty() && !o.seed;
  const auto controller = std::find_if(spec.controllers.begin(), spec.controllers.end(),
                                       [&](const control::ControllerSpec& c) { return c.name == s.controller; });
  if (controller == spec.controllers.end()) {
    std::vector<std::string> names;
    for (const auto& c : spec.controllers) names.push_back(c.name);
    complain("esc: error: experiment `{}` compares no controller `{}` (it compares {})\n", spec.name, s.controller,
             compiler::quoted_list(names, " and "));
    return kExitBadInput;
  }
  if (!controller->is_tree() && s.genome.size() != controller->genome_size()) {
    complain("esc: error: the stored genome of {} has {} genes, but {} in experiment `{}` has {} ({})\n", s.controller,
             s.genome.size(), s.controller, spec.name, controller->genome_size(), controller->architecture());
    return kExitBadInput;
  }
  eval::Evaluator evaluator(spec);
  Collect trace;
  const eval::Evaluation result = evaluator.evaluate(*controller, s.genome, s.seed, &trace);
  int status = kExitOk;
  if (faithful && s.fitness && result.fitness != *s.fitness) {
    complain("esc: error: {} run {} scores {:.17g} now, but {:.17g} when it ran: the simulation has changed\n",
             s.controller, s.run + 1, result.fitness, *s.fitness);
    status = kExitBadInput;
  }
  std::string descriptors;
  for (std::size_t i = 0; i < result.descriptors.size() && i < spec.descriptors.size(); ++i)
    descriptors += fmt::format("{}{} {:.17g}", descriptors.empty() ? "" : ", ", spec.descriptors[i].name,
                               result.descriptors[i]);
  if (faithful && !s.member_descriptors.empty() && result.descriptors != s.member_descriptors) {
    std::string stored;
    for (const double d : s.member_descriptors) stored += fmt::format("{}{:.17g}", stored.empty() ? "" : ", ", d);
    complain("esc: error: {} run {} {} has the descriptors {} now, but {} when it ran: the simulation has changed\n",
             s.controller, s.run + 1, s.member, descriptors, stored);
    status = kExitBadInput;
  }
  if (faithful && s.stored != nullptr) {
    const std::string difference = first_difference(trace.steps, *s.stored);
    if (!difference.empty()) {
      complain("esc: error: {} run {}: {}\n", s.controller, s.run + 1, difference);
      status = kExitBadInput;
    }
  }
  std::vector<eval::TraceStep> drawn;
  for (const eval::TraceStep& t : trace.steps)
    if (std::binary_search(epochs.begin(), epochs.end(), t.epoch)) drawn.push_back(t);

  // Named for what was replayed: another experiment's or another seed's files stand beside
  // the faithful replay's, never over them.
  std::string stem = fmt::format("replay-{}-run-{:02}", s.controller, s.run + 1);
  if (!s.member.empty()) stem += "-" + s.member;
  std::replace(stem.begin(), stem.end(), ' ', '-');
  if (!o.script.empty()) stem += "-in-" + spec.name;
  if (o.seed) stem += fmt::format("-seed-{}", *o.seed);
  std::error_code ec;
  fs::create_directories(out, ec);
  report::TrajectoryFigure figure;
  figure.title = fmt::format("{} ({}), run {}{}, in experiment {}", s.controller, controller->architecture(), s.run + 1,
                             s.member.empty() ? "" : ", " + s.member, spec.name);
  const int decimals = fitness_decimals(result.fitness, 2);
  figure.subtitle = fmt::format("fitness {:.{}f} over {} epoch{} of {} steps; {} drawn; arena {}; evaluation seed {}",
                                result.fitness, decimals, spec.epochs, spec.epochs == 1 ? "" : "s", spec.steps, epochs_text(epochs, spec.epochs),
                                spec.arena_name, s.seed);
  figure.arena = spec.arena;
  figure.robot_radius_m = spec.robot.body_radius_m;
  figure.choices = controller->choice_names();
  figure.steps = drawn;
  app::write_atomically(out / (stem + ".svg"), report::trajectory_svg(figure));
  app::write_atomically(out / (stem + ".csv"), report::trajectory_csv(drawn, figure.choices, spec.robot.control_step_s));
  // A member whose evaluation is not known (a state saved before origins were kept) is
  // replayed with its run's best's seed: its stored value is printed beside.
  const std::string stored_member =
      s.member_fitness ? fmt::format("; {:.17g} in its own evaluation", *s.member_fitness) : std::string();
  std::string agrees;
  if (faithful && status == kExitOk && s.stored != nullptr) agrees = ", identical to the stored replay";
  else if (faithful && status == kExitOk && !s.member.empty() && s.fitness) agrees = ", as in its own evaluation";
  say("esc: replayed {} run {}{} in {} (fitness {:.{}f}{}{}): {}/{}.svg, .csv\n", s.controller, s.run + 1,
      s.member.empty() ? "" : " " + s.member, spec.name, result.fitness, decimals, stored_member, agrees, out.string(),
      stem);
  // A member's descriptors place it in its cell: shown, and checked above against the stored.
  if (!s.member.empty() && !descriptors.empty())
    say("esc: {} descriptors: {}{}\n", s.member, descriptors,
        faithful && status == kExitOk && !s.member_descriptors.empty() ? " (as stored)" : "");
  if (o.animate) {
    const std::optional<fs::path> movie = write_animation(figure, out / stem);
    if (!movie) return kExitBadInput;
    say("esc: animation: {}\n", movie->string());
  }
  return status;
}

// Where a source's stored run is (app::locate_run), as an absolute path: `.` given from
// inside a run's directory has one above it.
app::RunLocation locate(const fs::path& dir) {
  std::error_code ec;
  return app::locate_run(fs::absolute(dir, ec).lexically_normal());
}

// The stored experiment to replay: the run's one experiment, or the study condition
// `at.condition`. Nullopt after printing an error (a study's directory names no condition).
std::optional<store::StoredExperiment> load_stored(const app::RunLocation& at, app::Events& events) {
  std::vector<store::StoredExperiment> all = app::read_stored(at, at.root, events);
  const bool study = !all.empty() && all.front().condition;
  if (!study && at.condition.empty()) {
    if (all.size() == 1) return std::move(all.front());
    return app::read_single(at.root);   // throws, saying what it holds instead
  }
  std::vector<std::string> directories;
  for (store::StoredExperiment& e : all) {
    if (!e.condition) continue;
    if (e.condition->directory == at.condition) return std::move(e);
    directories.push_back(e.condition->directory);
  }
  if (at.condition.empty())
    complain("esc: error: {} holds study `{}`: replay one of its conditions, e.g. esc replay {} (its conditions: {})\n",
             at.root.string(), all.front().condition->study, (at.root / directories.front()).string(),
             compiler::quoted_list(directories, ", "));
  else if (const auto c = std::find_if(all.front().controllers.begin(), all.front().controllers.end(),
                                        [&](const store::StoredController& k) { return k.name == at.condition; });
           !study && c != all.front().controllers.end())
    complain("esc: error: {} holds controller {}'s files: esc replay {} --controller {}\n",
             (at.root / at.condition).string(), c->name, at.root.string(), c->name);
  else
    complain("esc: error: {} is not a condition of the {} in {} (its conditions: {})\n", at.condition,
             study ? fmt::format("study `{}`", all.front().condition->study) : "run", at.root.string(),
             directories.empty() ? "none: it holds one experiment" : compiler::quoted_list(directories, ", "));
  return std::nullopt;
}

}  // namespace

int replay_command(const ReplayOptions& o) {
  std::error_code ec;
  const bool genome_file = fs::is_regular_file(o.source, ec);
  // The run directory: SOURCE itself, or the one a genome file was written into (absolute
  // first: a bare `run-01.best.json` has no parents to climb).
  const fs::path dir = genome_file ? fs::absolute(o.source, ec).parent_path().parent_path() : o.source;
  const app::RunLocation at = locate(dir);
  if (genome_file && !at.found && o.script.empty()) {
    complain("esc: error: {} is not inside a run directory: give the experiment to replay it in with --script FILE "
             "[--experiment NAME]\n", o.source.string());
    return kExitUsage;
  }
  if (o.evaluations && (genome_file || !o.script.empty() || o.seed || o.member || o.animate || !o.epochs.empty())) {
    complain("esc: error: --evaluations makes a stored run again as it ran: give a run directory, without --script, "
             "--seed, --member, --epochs or --animate\n");
    return kExitUsage;
  }
  if (o.over_arena && !o.evaluations) {
    complain("esc: error: --arena draws a run's evaluations (--evaluations) over its arena; give --evaluations too\n");
    return kExitUsage;
  }
  if (!o.experiment.empty() && o.script.empty()) {
    complain("esc: error: --experiment names an experiment of --script FILE; give the script too\n");
    return kExitUsage;
  }
  TerminalEvents events;
  std::optional<store::StoredExperiment> stored;
  if (at.found || !genome_file) {
    stored = at.found ? load_stored(at, events) : app::read_single(dir);
    if (!stored) return kExitUsage;
  }

  std::vector<Subject> subjects;
  if (genome_file) {
    auto s = genome_subject(o.source, o);
    if (!s) return kExitBadInput;
    subjects.push_back(std::move(*s));
  } else {
    subjects = stored_subjects(*stored, o);
    if (subjects.empty()) return kExitBadInput;
  }

  // The experiment: the stored one, compiled from the sources the run stored (whatever has
  // happened to the script since), with its settings; or one of another script.
  const app::StoredRun run{stored ? &*stored : nullptr, at.root, dir};
  const eval::ExperimentSpec experiment =
      o.script.empty() ? app::experiment_of_run(run, default_compile_options(), events)
                       : app::experiment_for_run(run, o.script, o.experiment, default_compile_options(), events);
  const eval::ExperimentSpec* spec = &experiment;

  if (o.member) {
    if (!stored) {
      complain("esc: error: --member picks a member of a run directory's front or archive, not of a genome file\n");
      return kExitUsage;
    }
    const eval::ExperimentSpec ran = o.script.empty() ? experiment
                                                      : app::experiment_of_run(run, default_compile_options(), events);
    for (Subject& s : subjects)
      if (!pick_member(s, app::final_members(run, ran, s.controller, s.run), *o.member)) return kExitBadInput;
  }
  if (o.seed)   // over the stored evaluation's, a member's too
    for (Subject& s : subjects) s.seed = *o.seed;
  const auto epochs = parse_epochs(o.epochs, spec->epochs);
  if (!epochs) return kExitUsage;
  const fs::path out = !o.out.empty() ? o.out : genome_file ? o.source.parent_path() : dir;
  app::require_writable(out, "the replay's files cannot be written there",
                        fmt::format("write them elsewhere: esc replay {} --out DIR2", o.source.string()));
  int status = kExitOk;
  if (o.evaluations) {
    for (const Subject& s : subjects)
      status = std::max(status, replay_evaluations(run, experiment, s.controller, s.run, o, out));
    return status;
  }
  for (const Subject& s : subjects) status = std::max(status, replay_one(*spec, s, o, *epochs, out));
  return status;
}

}  // namespace esc::cli
