#pragma once
// A checked, fully resolved experiment: everything a run needs, produced by the compiler
// from a script. Runtime code sees only this, never the parse tree.
#include <algorithm>
#include <any>
#include <charconv>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "runtime/control/controller.hpp"
#include "runtime/control/controller_spec.hpp"
#include "runtime/control/graph_net.hpp"
#include "runtime/evo/gp/gp.hpp"
#include "runtime/evo/neat/neat_settings.hpp"
#include "runtime/evo/registry.hpp"
#include "runtime/expr/observables.hpp"
#include "runtime/expr/program.hpp"
#include "runtime/expr/step_aggregate.hpp"
#include "runtime/sim/arena.hpp"
#include "runtime/sim/formation.hpp"
#include "runtime/sim/robot_params.hpp"

namespace esc::eval {

// Fitness of one evaluation: the sum over epochs and steps of `step`, evaluated after the
// physics of each control step. An epoch ends early after the first step at which any
// `stop_when` program is non-zero (that step's term still counts). The end terms are added
// once at the end of each epoch (`epoch_end`) and of the evaluation (`evaluation_end`): they
// read the last step's frame followed by the aggregates of expr::aggregate over the epoch
// (the evaluation), one count per experiment-wide choice id, then the values of the term's
// step aggregates (`mean(speed)`), aggregate k in slot ExperimentSpec::step_aggregate_slot() + k.
// The most robots in a group (`robot NAME x N`): the crowd of esc bench's scaling and a margin.
inline constexpr int kMaxRobots = 256;

// How a descriptor's per-epoch values make the evaluation's, and a group's robots' terms the
// group's (Mean, Sum, Min, Max only).
enum class Reduction { Mean, Sum, Min, Max, First, Last };

// `n` robots' values value(0) ... value(n - 1), in robot order, reduced by `over` (Mean, Sum,
// Min or Max).
template <class Value>
[[nodiscard]] double reduce_over_robots(std::size_t n, Reduction over, const Value& value) {
  if (over == Reduction::Min || over == Reduction::Max) {
    double r = value(0);
    for (std::size_t i = 1; i < n; ++i) r = over == Reduction::Min ? std::min(r, value(i)) : std::max(r, value(i));
    return r;
  }
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) sum += value(i);
  return over == Reduction::Mean ? sum / static_cast<double>(n) : sum;
}

struct FitnessSpec {
  std::string name;
  // Every term (step, epoch, evaluation) is each robot's on its own frame, made the group's by
  // this (`over robots min`): a robot alone's is its own whatever it says.
  Reduction over_robots = Reduction::Mean;
  expr::Program step;
  std::vector<expr::Program> stop_when;
  std::optional<expr::Program> epoch_end;
  std::optional<expr::Program> evaluation_end;
  std::vector<expr::StepAggregate> epoch_aggregates;        // read by epoch_end, over its epoch
  std::vector<expr::StepAggregate> evaluation_aggregates;   // read by evaluation_end, over every step
};

// The range an objective's or a descriptor's values are declared to lie in (`in [lo, hi]`):
// what a hypervolume's reference point, a QD-score's offset and an archive's cells are
// computed from. Values outside it are kept as measured; only the algorithms clamp.
struct DeclaredRange {
  double lower = 0.0;
  double upper = 0.0;
  friend bool operator==(const DeclaredRange&, const DeclaredRange&) = default;
};

// One objective of an experiment that declares several (`fitness F in [..]`, then
// `objective G minimize in [..]`): index 0 is the fitness, always maximised.
struct ObjectiveSpec {
  std::string name;                          // the fitness declaration's
  bool minimize = false;
  std::optional<DeclaredRange> range;
};

// A behavior descriptor (`descriptor NAME: EXPR in [lo, hi] by REDUCTION`): an end term,
// evaluated at the end of every epoch and reduced over the epochs, or once at the end of
// the evaluation over its aggregates (`at_evaluation`); its step aggregates fold the steps
// of the epoch (of the evaluation). A `positions(K)` descriptor is 2K of these, each an
// At aggregate of `x` or `y`.
struct DescriptorSpec {
  std::string name;
  expr::Program program;
  std::vector<expr::StepAggregate> aggregates;
  bool at_evaluation = false;
  Reduction reduce = Reduction::Mean;
  DeclaredRange range;
  Reduction over_robots = Reduction::Mean;   // a group's robots' values made the group's (`over robots max`)
};

// `success when NAME CMP THRESHOLD`: an evaluation succeeds when the value it measured of an
// objective or a descriptor passes the test. The value is the one the script declares: a
// minimised objective's own value (not the negation optimizers are told), a descriptor's
// value reduced over the epochs. Success rates and evaluations to success compare methods
// whose fitnesses differ (novelty search has none): eval/success.hpp,
// report/success_comparisons.hpp.
struct SuccessSpec {
  enum class Of { Objective, Descriptor };
  enum class Test { Below, AtMost, Above, AtLeast };   // <, <=, >, >=
  std::string name;              // the objective's (fitness declaration's) or descriptor's
  Of of = Of::Objective;
  // Objective: 0 is the fitness, i > 0 is further[i - 1] (evo::Outcome::objectives' order);
  // Descriptor: the index in descriptors.
  std::size_t index = 0;
  Test test = Test::Above;
  double threshold = 0.0;        // in SI, as the measured values

  [[nodiscard]] bool passes(double value) const noexcept {
    switch (test) {
      case Test::Below: return value < threshold;
      case Test::AtMost: return value <= threshold;
      case Test::Above: return value > threshold;
      case Test::AtLeast: return value >= threshold;
    }
    return false;
  }
  // "reach_goal > -0.0171875": the resolved setting `success`, and the label of the tables.
  [[nodiscard]] std::string text() const {
    static constexpr const char* kTests[] = {"<", "<=", ">", ">="};
    char number[32];
    const auto written = std::to_chars(number, number + sizeof number, threshold);
    return name + " " + kTests[static_cast<int>(test)] + " " + std::string(number, written.ptr);
  }
};

// A supervised behavior that is another experiment's evolved controller
// (`behavior avoid = evolved from experiment E controller C`): the experiment E must run
// first; the best genome of C over all its runs fills each target's FixedController.
struct Dependency {
  std::string experiment;           // E
  std::string controller;           // C, one of E's compared controllers
  // Where to put it: (index in `controllers`, index in that controller's `behaviors`).
  std::vector<std::pair<std::size_t, std::size_t>> targets;
};

// A setting a study condition gives an experiment this one depends on (`energy.generations
// 60`): applied to that experiment where it runs, before the command line's, so that it runs
// into a cache entry of its own. `path` names the dependency, then, for a setting further
// down, that one's dependency, and so on (`energy.stop.generations`: energy, stop).
struct DependencySetting {
  std::vector<std::string> path;
  std::string key;
  std::string value;                // as written in the script, without spaces
};

// `start from experiment E` / `evaluate from experiment E`: every run r begins with the
// best genome of run r (modulo E's run count) of E's controller of the same name, which
// must run first. Evaluating only, a run is one generation holding that genome alone;
// starting from it, generation 0's parents are copies of it and offspring 0 is it unchanged
// (a tree: generation 0 is bred from copies of it, and individual 0 is it unchanged).
struct StartFrom {
  // One of E's finished runs: what a run here starts from.
  struct Origin {
    int run = 0;                    // E's run, from 0
    double fitness = 0.0;           // its best fitness in E
    std::vector<double> genome;     // its best genome (a tree: encoded, evo/gp/codec.hpp)
  };
  std::string experiment;
  bool evaluate_only = false;
  // Filled in before running: [controller index][E's run] -> that run's best.
  std::vector<std::vector<Origin>> genomes;

  // Where run `run` of controller `index` starts from; null when nothing was filled in.
  [[nodiscard]] const Origin* origin(std::size_t index, int run) const noexcept {
    if (index >= genomes.size() || genomes[index].empty()) return nullptr;
    return &genomes[index][static_cast<std::size_t>(run) % genomes[index].size()];
  }
};

// How a compared controller evolves: the registered algorithm and its settings (the
// algorithm's own type; empty when the experiment gives it none).
struct Evolution {
  const evo::Algorithm* algorithm = nullptr;
  std::any settings;
};

// `members_every`'s default: a front every 10 generations keeps 100 of a 1000-generation
// run's, enough to follow it, at a tenth of the bytes (docs/results-store.md measures them).
inline constexpr int kMembersEvery = 10;

struct ExperimentSpec {
  // What evolves a compared controller the script names no algorithm for: a network, a tree,
  // a `neat(...)` network.
  static constexpr const char* kDefaultNetworks = "es";
  static constexpr const char* kDefaultTrees = "gp";
  static constexpr const char* kDefaultGraphs = "neat";
  // The algorithm whose settings hold the tree kind's operators and the trees' generations:
  // every algorithm that evolves trees varies them with GP's (`evolve gp(...)`).
  static constexpr const char* kTreeOperators = "gp";
  // The algorithm whose settings hold the graph kind's operators: every algorithm that
  // evolves `neat(...)` networks varies them with NEAT's (`evolve neat(...)`, else its
  // defaults).
  static constexpr const char* kGraphOperators = "neat";

  std::string name;
  std::string arena_name;
  sim::ArenaSpec arena;
  sim::RobotParams robot;
  // The group: this many robots of `robot`'s body in the arena, each driven by its own instance
  // of the controller evaluated; every step term, stop condition and end term is evaluated on
  // each robot's frame, the terms averaged over the robots (docs/groups.md). 1: a robot alone.
  int robots = 1;   // at most kMaxRobots
  // A group of several bodies (`robot khepera x 2, lit_khepera x 3`): each body and its robots,
  // in robot order (robots 0 and 1 the first body's, ...), `robot` the first body, the counts
  // adding up to `robots`. Empty: every robot has `robot`'s body. The bodies share what one
  // controller reads, their drive and their step (compiler::group_difference checks it), and
  // may differ in anything else, their shapes included.
  struct GroupBody {
    std::string name;
    sim::RobotParams params;
    int count = 1;
  };
  std::vector<GroupBody> bodies;
  // A network's genome holds this many networks' weights, one per role, evolved together;
  // robot i is driven by role i mod roles. 1: the clonal team, one genome for every robot.
  // At most `robots`, and only for networks of fixed topology (check_group).
  int roles = 1;
  sim::Formation formation;   // where a group's robots start each epoch (`formation line 10cm`)
  // The radii (m) the group's clusters are counted within, each read from slots clusters + k,
  // largest_cluster + k and cluster_size + k (`clusters(15cm)`): at most kMaxClusterRadii.
  std::vector<double> cluster_radii;
  FitnessSpec fitness;
  // Declared objectives: empty for an experiment with the fitness alone and no range;
  // otherwise objectives[0] describes `fitness` and objectives[i > 0] is further[i - 1].
  std::vector<ObjectiveSpec> objectives;
  std::vector<FitnessSpec> further;
  std::vector<DescriptorSpec> descriptors;
  std::optional<SuccessSpec> success;   // `success when ...`; none: success is not measured
  // `stop at success`: a run ends after the generation whose evaluations first passed the
  // test (runs.stopped `stop_at_success`), as Lehman & Stanley's do; the evaluations to
  // success are those of a run that goes on.
  bool stop_at_success = false;
  // A front (NSGA-II's first, novelty and fitness) is stored at the generations that are
  // multiples of this and at each run's last, and not again where it equals the last one
  // stored (docs/results-store.md); an archive's changes are stored every generation. What is
  // stored, never what is computed: results do not depend on it.
  int members_every = kMembersEvery;
  int epochs = 10;
  int steps = 150;                  // control steps per epoch (at most)
  int runs = 10;
  std::uint64_t seed = 1;
  // The experiment's generations: every network's, and a tree's without GP's settings (trees
  // run for GP's own `generations`, generations_for).
  int generations = 250;
  // The settings of the algorithms, by name (the algorithm's own settings type:
  // evo::EsSettings for `es`, evo::gp::GpSettings for `gp`, ...): the ES's in every compiled
  // experiment, GP's where the script gives them (`evolve gp(...)`, the trees' operators),
  // another's where it evolves a compared controller or the script gives them.
  std::map<std::string, std::any> algorithm_settings;
  // What evolves the networks compared without `by` (`--set networks=cmaes`).
  std::string networks{kDefaultNetworks};
  std::vector<control::ControllerSpec> controllers;   // the `compare` list, in order
  // Distinct choice ids over the compared controllers (control::Choice::id is below it): the
  // counts an end term can read.
  std::size_t choice_ids = 0;
  // Every setting as resolved, for the run directory ("epochs" -> "10", ...).
  std::map<std::string, std::string> resolved_settings;
  // Evolved behaviors to fill in before running, one per (experiment, controller) used.
  std::vector<Dependency> dependencies;
  std::optional<StartFrom> start_from;
  std::vector<DependencySetting> dependency_settings;

  // Experiments that must have run before this one (evolved behaviors, start genomes),
  // each named once, in the order they are first needed.
  [[nodiscard]] std::vector<std::string> needs() const {
    std::vector<std::string> n;
    const auto add = [&n](const std::string& x) {
      if (std::find(n.begin(), n.end(), x) == n.end()) n.push_back(x);
    };
    for (const Dependency& d : dependencies) add(d.experiment);
    if (start_from) add(start_from->experiment);
    return n;
  }

  // The experiments of needs() whose results were never filled in (frozen behaviors without
  // a genome, start genomes missing): what a program must prepare before running this one.
  [[nodiscard]] std::vector<std::string> unprepared() const {
    std::vector<std::string> n;
    const auto add = [&n](const std::string& x) {
      if (std::find(n.begin(), n.end(), x) == n.end()) n.push_back(x);
    };
    for (const Dependency& d : dependencies)
      for (const auto& [ci, bi] : d.targets) {
        if (ci >= controllers.size() || bi >= controllers[ci].behaviors.size()) continue;
        const auto* fixed = std::get_if<control::FixedController>(&controllers[ci].behaviors[bi].what);
        if (fixed != nullptr && (fixed->spec == nullptr || fixed->genome.empty())) add(d.experiment);
      }
    if (start_from && start_from->genomes.size() < controllers.size()) add(start_from->experiment);
    return n;
  }

  // The algorithm that evolves `c`: the one its `by` names, else `networks` for a network,
  // GP for a tree and NEAT for a `neat(...)` network; with its settings (algorithm_settings).
  [[nodiscard]] Evolution evolution_of(const control::ControllerSpec& c) const {
    const std::string& by = !c.evolved_by.empty() ? c.evolved_by
                            : c.is_tree()          ? kDefaultTrees
                            : c.is_graph()         ? kDefaultGraphs
                                                   : networks;
    Evolution e{evo::find_algorithm(by), {}};
    if (const auto it = algorithm_settings.find(by); it != algorithm_settings.end()) e.settings = it->second;
    return e;
  }
  // The settings of the algorithm called `algorithm`, of its own type S; null where the
  // experiment holds none.
  template <class S>
  [[nodiscard]] const S* settings_of(const std::string& algorithm) const {
    const auto it = algorithm_settings.find(algorithm);
    return it == algorithm_settings.end() ? nullptr : std::any_cast<S>(&it->second);
  }
  // The trees' operators and generations (GP's settings); null without `evolve gp`.
  [[nodiscard]] const evo::gp::GpSettings* tree_operators() const {
    return settings_of<evo::gp::GpSettings>(kTreeOperators);
  }

  // The slot of an end term's first step aggregate: after the frame, `steps` and the counts.
  [[nodiscard]] expr::Slot step_aggregate_slot() const noexcept {
    return expr::aggregate::count + static_cast<expr::Slot>(choice_ids);
  }
  [[nodiscard]] bool evaluates_only() const noexcept { return start_from && start_from->evaluate_only; }
  // Whether objective i (0: the fitness) is declared `minimize`: optimizers maximise, so they
  // see it negated (problem_of), and as_declared turns what they saw back.
  [[nodiscard]] bool minimized(std::size_t i) const noexcept { return i < objectives.size() && objectives[i].minimize; }
  // Objective i's value as optimizers see it from the value as declared, and back.
  [[nodiscard]] double as_declared(std::size_t i, double v) const noexcept { return minimized(i) ? -v : v; }
  // The experiment's generations as run: 1 when only evaluating stored controllers.
  [[nodiscard]] int experiment_generations() const noexcept { return evaluates_only() ? 1 : generations; }
  // Generations a compared controller evolves for: GP's for a tree, else the experiment's.
  [[nodiscard]] int generations_for(const control::ControllerSpec& c) const {
    const evo::gp::GpSettings* trees = c.is_tree() ? tree_operators() : nullptr;
    return trees != nullptr && !evaluates_only() ? trees->generations : experiment_generations();
  }
  // Individuals a compared controller evaluates in its first generation: its algorithm's
  // population (the ES's lambda, GP's population, ...), or 1 when the experiment only
  // evaluates stored genomes; 0 when its algorithm has no settings (refused at run time).
  [[nodiscard]] std::size_t evaluations_per_generation(const control::ControllerSpec& c) const {
    if (evaluates_only()) return 1;
    const Evolution e = evolution_of(c);
    if (e.algorithm == nullptr || !e.settings.has_value()) return 0;
    return e.algorithm->population(e.settings, problem_of(c));
  }
  // What evolving `c` asks of an optimizer, as far as sizes and declared ranges go (the
  // run adds its seed and start genome): the genome's length (0 for a tree), every
  // objective's range maximised (a minimised one's negated; infinite where undeclared) and
  // every descriptor's.
  [[nodiscard]] evo::Problem problem_of(const control::ControllerSpec& c) const {
    constexpr double inf = std::numeric_limits<double>::infinity();
    evo::Problem p;
    p.genome_size = genome_length(c);
    p.tree.primitives = c.primitives.get();
    if (c.is_graph()) {
      const evo::NeatSettings* neat = settings_of<evo::NeatSettings>(kGraphOperators);
      p.graph = {c.mlp.inputs.size(), static_cast<std::size_t>(c.output_count()),
                 control::graph_activation(control::output_activation(c.head)),
                 evo::graph_operators(neat != nullptr ? *neat : evo::NeatSettings{})};
    }
    if (c.is_tree()) p.tree.operators = tree_operators();
    p.objectives.assign(1 + further.size(), evo::Bounds{-inf, inf});
    for (std::size_t i = 0; i < objectives.size() && i < p.objectives.size(); ++i) {
      const ObjectiveSpec& o = objectives[i];
      if (!o.range) continue;
      p.objectives[i] = minimized(i) ? evo::Bounds{-o.range->upper, -o.range->lower}
                                   : evo::Bounds{o.range->lower, o.range->upper};
    }
    for (const DescriptorSpec& d : descriptors) p.descriptors.push_back({d.range.lower, d.range.upper});
    return p;
  }
  // The most generations of any compared controller (the experiment's when none is compared).
  [[nodiscard]] int max_generations() const {
    int g = controllers.empty() ? generations : 0;
    for (const auto& c : controllers) g = std::max(g, generations_for(c));
    return g;
  }
  // Generations of the whole campaign: every run of every controller.
  [[nodiscard]] std::int64_t total_generations() const {
    std::int64_t n = 0;
    for (const auto& c : controllers) n += static_cast<std::int64_t>(runs) * generations_for(c);
    return n;
  }
  // Every robot's body, in robot order.
  [[nodiscard]] std::vector<sim::RobotParams> robot_params() const {
    if (bodies.empty()) return std::vector<sim::RobotParams>(static_cast<std::size_t>(robots), robot);
    std::vector<sim::RobotParams> all;
    for (const GroupBody& b : bodies) all.insert(all.end(), static_cast<std::size_t>(b.count), b.params);
    return all;
  }
  // The body robot `i` has: its index in `bodies` (0 for a group of one body).
  [[nodiscard]] std::size_t body_of(std::size_t i) const noexcept {
    std::size_t b = 0;
    for (std::size_t first = 0; b < bodies.size(); ++b) {
      first += static_cast<std::size_t>(bodies[b].count);
      if (i < first) return b;
    }
    return 0;
  }
  // A genome of `c` here: its network's weights once per role (a tree's and a graph's, of any
  // length, have genome_size() 0).
  [[nodiscard]] std::size_t genome_length(const control::ControllerSpec& c) const {
    return c.genome_size() * static_cast<std::size_t>(roles);
  }
  // The size tables show for a controller: its genome's weights, or a tree's node limit.
  [[nodiscard]] std::size_t genome_size_of(const control::ControllerSpec& c) const {
    const evo::gp::GpSettings* trees = c.is_tree() ? tree_operators() : nullptr;
    return trees != nullptr ? static_cast<std::size_t>(trees->max_size) : genome_length(c);
  }
};

}  // namespace esc::eval
