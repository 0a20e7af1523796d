#include "app/replay.hpp"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <span>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/error.hpp"
#include "app/output_files.hpp"
#include "app/results.hpp"
#include "app/store_errors.hpp"
#include "app/stored_run.hpp"
#include "compiler/names.hpp"
#include "runtime/eval/campaign.hpp"
#include "runtime/eval/genome_fit.hpp"
#include "runtime/report/fitness_decimals.hpp"
#include "runtime/report/trajectory_csv.hpp"

namespace esc::app {

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
  std::string architecture;                   // of the controller that evolved it, as stored
};

struct Collect final : eval::TraceSink {
  std::vector<eval::TraceStep> steps;
  void on_step(const eval::TraceStep& t) override { steps.push_back(t); }
};

// "1,3-5" (epochs from 1) as indices from 0, in order.
std::vector<int> parse_epochs(const std::string& list, int epochs) {
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
    if (!ok || first < 1 || last < first || last > epochs)
      throw Error(ErrorKind::Request,
                  fmt::format("--epochs {}: `{}` is not an epoch or a range of epochs between 1 and {} (e.g. 1,3-5)",
                              list, item, epochs));
    for (auto e = static_cast<int>(first); e <= last; ++e)
      if (std::find(chosen.begin(), chosen.end(), e - 1) == chosen.end()) chosen.push_back(e - 1);
    at = comma + 1;
  }
  std::sort(chosen.begin(), chosen.end());
  return chosen;
}

// The run to replay of a stored controller: --run, else the run whose best evaluation is
// stored as the controller's replay, else its best run.
const eval::RunResult& pick_run(const store::StoredController& c, const std::optional<int>& run) {
  const auto& runs = c.finished;
  if (run) {
    const auto it = std::find_if(runs.begin(), runs.end(), [&](const eval::RunResult& r) { return r.run + 1 == *run; });
    if (it != runs.end()) return *it;
    throw Error(ErrorKind::Results,
                fmt::format("controller {} has no finished run {} ({} finished)", c.name, *run, runs.size()));
  }
  if (runs.empty())
    throw Error(ErrorKind::Results, fmt::format("controller {} has no finished run to replay", c.name));
  if (c.replay)
    for (const eval::RunResult& r : runs)
      if (r.run == c.replay->run) return r;
  return *std::max_element(runs.begin(), runs.end(), [](const eval::RunResult& a, const eval::RunResult& b) {
    return a.best_fitness < b.best_fitness;
  });
}

std::vector<Subject> stored_subjects(const store::StoredExperiment& stored, const ReplayRequest& o) {
  std::vector<Subject> subjects;
  std::vector<std::string> names;
  for (const store::StoredController& c : stored.controllers) {
    names.push_back(c.name);
    if (!o.controller.empty() && c.name != o.controller) continue;
    const eval::RunResult& r = pick_run(c, o.run);
    Subject s{c.name, r.run, r.seed, r.best_genome,
              eval::evaluation_seed(r.seed, r.best_generation, static_cast<std::size_t>(r.best_index)),
              r.best_fitness, nullptr, {}, {}, {}, c.architecture};
    if (c.replay && c.replay->run == r.run && c.replay->seed == s.seed) s.stored = &*c.replay;
    subjects.push_back(std::move(s));
  }
  if (subjects.empty()) {
    const auto near = compiler::closest(o.controller, names);
    throw Error(ErrorKind::Results,
                fmt::format("the run has no controller `{}`; it compares {}", o.controller,
                            compiler::quoted_list(names, " and ")),
                near ? fmt::format("did you mean `{}`?", *near) : std::string());
  }
  return subjects;
}

// Makes `s` the member `member` of its run's final front or archive.
void pick_member(Subject& s, const evo::Members& kept, std::int64_t member) {
  const bool front = kept.kind == evo::MemberKind::Front;
  const auto it = std::find_if(kept.members.begin(), kept.members.end(),
                               [&](const evo::Member& m) { return m.cell == member; });
  if (it == kept.members.end() || it->genome.empty()) {
    const std::optional<std::size_t> cells = kept.cells();
    if (!front && cells && (member < 0 || static_cast<std::size_t>(member) >= *cells))
      throw Error(ErrorKind::Results, fmt::format("{} run {}'s archive has no cell {}: its cells are numbered 0-{}",
                                                  s.controller, s.run + 1, member, *cells - 1));
    if (!front && it == kept.members.end())
      throw Error(ErrorKind::Results,
                  fmt::format("cell {} of {} run {}'s archive is empty ({} cells filled; esc export --table archive "
                              "lists them)", member, s.controller, s.run + 1, kept.members.size()));
    if (it == kept.members.end())
      throw Error(ErrorKind::Results, fmt::format("{} run {}'s final front has {} members, numbered from 0; {} is not one",
                                                  s.controller, s.run + 1, kept.members.size(), member));
    throw Error(ErrorKind::Results,
                fmt::format("{} run {}'s archive keeps behaviors, not the genomes that produced them: there is "
                            "nothing to replay in cell {}", s.controller, s.run + 1, member));
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
}

// A genome file written by `esc run` (CONTROLLER/run-NN.best.json).
Subject genome_subject(const fs::path& file, const ReplayRequest& o) {
  std::ifstream in(file);
  nlohmann::json j;
  Subject s;
  bool intact = false;
  std::optional<std::uint64_t> seed;
  try {
    j = nlohmann::json::parse(in);
    s.controller = j.at("controller").get<std::string>();
    s.run = j.at("run").get<int>() - 1;
    s.genome = j.at("genome").get<std::vector<double>>();
    s.fitness = j.at("fitness").get<double>();
    s.architecture = j.value("architecture", std::string());
    intact = genome_file_intact(j);
    if (intact && !o.seed) seed = genome_file_seed(j);
  } catch (const std::exception& e) {   // JSON errors, a seed that is not one
    throw Error(ErrorKind::Results, fmt::format("{} is not a genome file of esc run ({})", file.string(), e.what()));
  }
  if (!intact)
    throw Error(ErrorKind::Results,
                fmt::format("{} is damaged: its genome, fitness or seed does not match its checksum", file.string()));
  if (o.seed) s.seed = *o.seed;
  else if (seed) s.seed = *seed;
  else
    throw Error(ErrorKind::Results, fmt::format("{} does not say its evaluation's seed (written by an older esc): give "
                                                "--seed", file.string()));
  return s;
}

// The first difference between a replay and the stored one, or empty when bit-identical.
std::string first_difference(std::span<const eval::TraceStep> now, const store::StoredReplay& stored) {
  // A group's stored replay keeps at most eval::kMaxReplayRows rows, cut as trace_rows_kept cuts.
  if (!now.empty() && now.front().grouped) now = now.first(eval::trace_rows_kept(now, eval::kMaxReplayRows));
  if (now.size() != stored.steps.size())
    return fmt::format("{} steps instead of the stored {}", now.size(), stored.steps.size());
  for (std::size_t i = 0; i < now.size(); ++i) {
    const eval::TraceStep& a = now[i];
    const eval::TraceStep& b = stored.steps[i];
    // An older esc stored each epoch's last step before the epoch's end terms were counted.
    const bool epoch_end = i + 1 == now.size() || now[i + 1].epoch != a.epoch;
    const bool fitness = a.fitness == b.fitness || (epoch_end && !stored.end_terms_counted);
    const bool same = a.epoch == b.epoch && a.step == b.step && a.robot == b.robot && a.group == b.group &&
                      a.pose.x_m == b.pose.x_m && a.pose.y_m == b.pose.y_m &&
                      a.pose.heading_rad == b.pose.heading_rad && a.ir == b.ir && a.left_command == b.left_command &&
                      a.right_command == b.right_command && a.left_speed_mps == b.left_speed_mps &&
                      a.right_speed_mps == b.right_speed_mps && a.action == b.action && fitness &&
                      a.collided == b.collided && a.energy == b.energy;
    if (!same)
      return fmt::format("it differs from the stored replay at epoch {}, step {}{}", a.epoch + 1, a.step + 1,
                         a.grouped ? fmt::format(", robot {}", a.robot + 1) : std::string());
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

// Replays one subject in `spec` and writes its files.
ReplayedSubject replay_subject(const eval::ExperimentSpec& spec, const Subject& s, const ReplayRequest& o,
                               const std::vector<int>& epochs, const fs::path& out) {
  ReplayedSubject done;
  done.controller = s.controller;
  done.run = s.run;
  done.member = s.member;
  done.experiment = spec.name;
  done.faithful = o.script.empty() && !o.seed;
  const auto controller = std::find_if(spec.controllers.begin(), spec.controllers.end(),
                                       [&](const control::ControllerSpec& c) { return c.name == s.controller; });
  if (controller == spec.controllers.end()) {
    std::vector<std::string> names;
    for (const auto& c : spec.controllers) names.push_back(c.name);
    done.problems.push_back(fmt::format("experiment `{}` compares no controller `{}` (it compares {})", spec.name,
                                        s.controller, compiler::quoted_list(names, " and ")));
    return done;
  }
  if (const std::string why = eval::genome_problem(*controller, s.genome, spec.roles, s.architecture); !why.empty()) {
    done.problems.push_back(
        fmt::format("the stored genome of {} does not fit {} in experiment `{}`: {}", s.controller, s.controller, spec.name, why));
    return done;
  }
  eval::Evaluator evaluator(spec);
  Collect trace;
  const eval::Evaluation result = evaluator.evaluate(*controller, s.genome, s.seed, &trace);
  done.replayed = true;
  done.fitness = result.fitness;
  if (done.faithful && s.fitness && result.fitness != *s.fitness)
    done.problems.push_back(fmt::format("{} run {} scores {:.17g} now, but {:.17g} when it ran: the simulation has "
                                        "changed", s.controller, s.run + 1, result.fitness, *s.fitness));
  for (std::size_t i = 0; i < result.descriptors.size() && i < spec.descriptors.size(); ++i)
    done.descriptors.emplace_back(spec.descriptors[i].name, result.descriptors[i]);
  if (done.faithful && !s.member_descriptors.empty() && result.descriptors != s.member_descriptors) {
    std::string stored;
    for (const double d : s.member_descriptors) stored += fmt::format("{}{:.17g}", stored.empty() ? "" : ", ", d);
    done.problems.push_back(fmt::format("{} run {} {} has the descriptors {} now, but {} when it ran: the simulation "
                                        "has changed", s.controller, s.run + 1, s.member,
                                        descriptors_text(done.descriptors), stored));
  }
  if (done.faithful && s.stored != nullptr) {
    const std::string difference = first_difference(trace.steps, *s.stored);
    if (!difference.empty()) done.problems.push_back(fmt::format("{} run {}: {}", s.controller, s.run + 1, difference));
  }
  const bool agrees = done.faithful && done.problems.empty();
  done.identical_to_stored_replay = agrees && s.stored != nullptr;
  done.as_in_own_evaluation = agrees && s.stored == nullptr && !s.member.empty() && s.fitness;
  done.descriptors_as_stored = agrees && !s.member_descriptors.empty();
  done.own_fitness = s.member_fitness;
  for (const eval::TraceStep& t : trace.steps)
    if (std::binary_search(epochs.begin(), epochs.end(), t.epoch)) done.drawn.push_back(t);

  // Named for what was replayed: another experiment's or another seed's files stand beside
  // the faithful replay's, never over them.
  std::string stem = fmt::format("replay-{}-run-{:02}", s.controller, s.run + 1);
  if (!s.member.empty()) stem += "-" + s.member;
  std::replace(stem.begin(), stem.end(), ' ', '-');
  if (!o.script.empty()) stem += "-in-" + spec.name;
  if (o.seed) stem += fmt::format("-seed-{}", *o.seed);
  done.out = out;
  done.stem = stem;
  std::error_code ec;
  fs::create_directories(out, ec);
  report::TrajectoryFigure& frame = done.frame;
  frame.title = fmt::format("{} ({}), run {}{}, in experiment {}", s.controller, controller->architecture(), s.run + 1,
                            s.member.empty() ? "" : ", " + s.member, spec.name);
  const int decimals = report::fitness_decimals(result.fitness, 2);
  frame.subtitle = fmt::format("fitness {:.{}f} over {} epoch{} of {} steps; {} drawn; arena {}{}; evaluation seed {}",
                               result.fitness, decimals, spec.epochs, spec.epochs == 1 ? "" : "s", spec.steps,
                               epochs_text(epochs, spec.epochs), spec.arena_name,
                               spec.robots > 1 ? fmt::format(", {} robots", spec.robots) : std::string(), s.seed);
  frame.arena = spec.arena;
  for (const sim::RobotParams& r : spec.robot_params()) frame.bodies.push_back({r.body_radius_m, r.outline});
  frame.choices = controller->choice_names();
  write_atomically(out / (stem + ".svg"), report::trajectory_svg(done.figure()));
  // A group's IR columns are as many as its body with the most has (named as the first
  // body names them): a robot's beyond its own read 0, as its frame held them.
  std::size_t ir_count = 0;
  for (const sim::RobotParams& r : spec.robot_params()) ir_count = std::max(ir_count, r.ir.mounts.size());
  write_atomically(out / (stem + ".csv"), report::trajectory_csv(done.drawn, frame.choices, spec.robot.control_step_s,
                                                                 {spec.robot.ir.name, ir_count, spec.robot.ground.name}));
  return done;
}

// Where a source's stored run is (locate_run), as an absolute path: `.` given from inside a
// run's directory has one above it.
RunLocation locate(const fs::path& dir) {
  std::error_code ec;
  return locate_run(fs::absolute(dir, ec).lexically_normal());
}

// The stored experiment to replay: the run's one experiment, or the study condition
// `at.condition`.
store::StoredExperiment load_stored(const RunLocation& at, Events& events) {
  std::vector<store::StoredExperiment> all = read_stored(at, at.root, events);
  const bool study = !all.empty() && all.front().condition;
  if (!study && at.condition.empty()) {
    if (all.size() == 1) return std::move(all.front());
    return read_single(at.root);   // throws, saying what it holds instead
  }
  std::vector<std::string> directories;
  for (store::StoredExperiment& e : all) {
    if (!e.condition) continue;
    if (e.condition->directory == at.condition) return std::move(e);
    directories.push_back(e.condition->directory);
  }
  if (at.condition.empty())
    throw Error(ErrorKind::Request,
                fmt::format("{} holds study `{}`: replay one of its conditions, e.g. esc replay {} (its conditions: {})",
                            at.root.string(), all.front().condition->study, (at.root / directories.front()).string(),
                            compiler::quoted_list(directories, ", ")));
  if (const auto c = std::find_if(all.front().controllers.begin(), all.front().controllers.end(),
                                  [&](const store::StoredController& k) { return k.name == at.condition; });
      !study && c != all.front().controllers.end())
    throw Error(ErrorKind::Request, fmt::format("{} holds controller {}'s files: esc replay {} --controller {}",
                                                (at.root / at.condition).string(), c->name, at.root.string(), c->name));
  throw Error(ErrorKind::Request,
              fmt::format("{} is not a condition of the {} in {} (its conditions: {})", at.condition,
                          study ? fmt::format("study `{}`", all.front().condition->study) : "run", at.root.string(),
                          directories.empty() ? "none: it holds one experiment" : compiler::quoted_list(directories, ", ")));
}

}  // namespace

std::string descriptors_text(const std::vector<std::pair<std::string, double>>& descriptors) {
  std::string text;
  for (const auto& [name, value] : descriptors) text += fmt::format("{}{} {:.17g}", text.empty() ? "" : ", ", name, value);
  return text;
}

ReplayOutcome replay(const ReplayRequest& o, const compiler::CompileOptions& options, Events& events,
                     ReplayListener& listener) {
  std::error_code ec;
  const bool genome_file = fs::is_regular_file(o.source, ec);
  // The run directory: SOURCE itself, or the one a genome file was written into (absolute
  // first: a bare `run-01.best.json` has no parents to climb).
  const fs::path dir = genome_file ? fs::absolute(o.source, ec).parent_path().parent_path() : o.source;
  const RunLocation at = locate(dir);
  if (genome_file && !at.found && o.script.empty())
    throw Error(ErrorKind::Request, fmt::format("{} is not inside a run directory: give the experiment to replay it in "
                                                "with --script FILE [--experiment NAME]", o.source.string()));
  if (o.evaluations && (genome_file || !o.script.empty() || o.seed || o.member || o.animate || !o.epochs.empty()))
    throw Error(ErrorKind::Request, "--evaluations makes a stored run again as it ran: give a run directory, without "
                                    "--script, --seed, --member, --epochs or --animate");
  if (o.over_arena && !o.evaluations)
    throw Error(ErrorKind::Request,
                "--arena draws a run's evaluations (--evaluations) over its arena; give --evaluations too");
  if (!o.experiment.empty() && o.script.empty())
    throw Error(ErrorKind::Request, "--experiment names an experiment of --script FILE; give the script too");
  std::optional<store::StoredExperiment> stored;
  if (at.found || !genome_file) stored = at.found ? load_stored(at, events) : read_single(dir);

  std::vector<Subject> subjects;
  if (genome_file) subjects.push_back(genome_subject(o.source, o));
  else subjects = stored_subjects(*stored, o);

  // The experiment: the stored one, compiled from the sources the run stored (whatever has
  // happened to the script since), with its settings; or one of another script.
  const StoredRun run{stored ? &*stored : nullptr, at.root, dir};
  const eval::ExperimentSpec experiment = o.script.empty()
                                              ? experiment_of_run(run, options, events)
                                              : experiment_for_run(run, o.script, o.experiment, options, events);

  if (o.member) {
    if (!stored)
      throw Error(ErrorKind::Request,
                  "--member picks a member of a run directory's front or archive, not of a genome file");
    const eval::ExperimentSpec ran = o.script.empty() ? experiment : experiment_of_run(run, options, events);
    for (Subject& s : subjects) pick_member(s, final_members(run, ran, s.controller, s.run), *o.member);
  }
  if (o.seed)   // over the stored evaluation's, a member's too
    for (Subject& s : subjects) s.seed = *o.seed;
  const std::vector<int> epochs = parse_epochs(o.epochs, experiment.epochs);
  const fs::path out = !o.out.empty() ? o.out : genome_file ? o.source.parent_path() : dir;
  require_writable(out, "the replay's files cannot be written there",
                   fmt::format("write them elsewhere: esc replay {} --out DIR2", o.source.string()));
  ReplayOutcome outcome;
  if (o.evaluations) {
    for (const Subject& s : subjects) {
      const std::string who = fmt::format("{} run {}", s.controller, s.run + 1);
      outcome.evaluations.push_back(replay_evaluations(
          run, experiment, s.controller, s.run, o.threads, o.over_arena, out,
          [&](int done, int generations) { listener.generation_made_again(who, done, generations); }));
      listener.evaluations_replayed(outcome.evaluations.back());
    }
    return outcome;
  }
  for (const Subject& s : subjects) {
    outcome.subjects.push_back(replay_subject(experiment, s, o, epochs, out));
    listener.replayed(outcome.subjects.back());
  }
  return outcome;
}

}  // namespace esc::app
