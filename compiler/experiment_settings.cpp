#include "compiler/experiment_settings.hpp"

#include <array>
#include <limits>

#include <fmt/format.h>

#include "compiler/algorithm_options.hpp"
#include "compiler/lower_evolution.hpp"
#include "compiler/setting_values.hpp"
#include "compiler/table_lookup.hpp"

namespace esc::compiler {

namespace {

using X = eval::ExperimentSpec;
using Row = ExperimentSetting;
constexpr long long kIntMax = std::numeric_limits<int>::max();

// A count of at least 1; its text.
template <int X::*Field>
bool read_positive(const Row& r, X& x, const ast::Value& v, Sink& sink) {
  const auto n = read_count(v, r.key, 1, kIntMax, sink);
  if (n) x.*Field = static_cast<int>(*n);
  return n.has_value();
}
template <int X::*Field>
std::string count_text(const X& x) {
  return std::to_string(x.*Field);
}

}  // namespace

const std::vector<std::string>& formation_words() {
  static const std::vector<std::string> words = {"random", "line", "circle", "at"};   // sim::FormationKind's order
  return words;
}

const std::vector<ExperimentSetting>& experiment_settings() {
  static const std::vector<ExperimentSetting> table = {
      {"epochs", "evaluations of a controller per generation, each from a new start",
       &read_positive<&X::epochs>, &count_text<&X::epochs>},
      {"steps", "control steps per epoch, at most",
       &read_positive<&X::steps>, &count_text<&X::steps>},
      {"runs", "independent runs of each compared controller",
       &read_positive<&X::runs>, &count_text<&X::runs>},
      {"seed", "the master seed every run's streams derive from (0 .. 2^64 - 1)",
       [](const Row& r, X& x, const ast::Value& v, Sink& k) {
         const auto n = read_seed(v, r.key, k);
         if (n) x.seed = *n;
         return n.has_value();
       },
       [](const X& x) { return std::to_string(x.seed); }},
      // Resolved only for a group, so that runs from before it keep their settings.
      {"robots", "robots of the experiment's body in the arena, each driven by its own copy of its role's controller",
       [](const Row& r, X& x, const ast::Value& v, Sink& k) {
         if (x.bodies.size() > 1) {
           k.error(v.where, "the group is of several bodies, each with its count: change them in the `robot` item");
           return false;
         }
         const auto n = read_count(v, r.key, 1, eval::kMaxRobots, k);
         if (n) x.robots = static_cast<int>(*n);
         return n.has_value();
       },
       [](const X& x) { return x.robots == 1 ? std::string() : count_text<&X::robots>(x); }},
      // Resolved only for several roles, so that runs from before it keep their settings;
      // check_group checks it against the group and the controllers.
      {"roles", "genomes evolved together, one per role: robot i plays role i mod roles (1: the clonal team)",
       [](const Row& r, X& x, const ast::Value& v, Sink& k) {
         const auto n = read_count(v, r.key, 1, eval::kMaxRobots, k);
         if (n) x.roles = static_cast<int>(*n);
         return n.has_value();
       },
       [](const X& x) { return x.roles == 1 ? std::string() : count_text<&X::roles>(x); }},
      // The formation's rows, resolved only when not random, so that runs from before them keep
      // their settings; check_formation (setting_keys.cpp) checks them against the group.
      {"formation", "where a group's robots start each epoch: random, line, circle or at (docs/groups.md)",
       [](const Row& r, X& x, const ast::Value& v, Sink& k) {
         const auto i = read_word(v, r.key, formation_words(), k);
         if (i) x.formation.kind = static_cast<sim::FormationKind>(*i);
         return i.has_value();
       },
       [](const X& x) {
         return x.formation.kind == sim::FormationKind::Random
                    ? std::string()
                    : formation_words()[static_cast<std::size_t>(x.formation.kind)];
       }},
      {"formation_spacing", "a line's distance between neighbours' centres, a circle's radius",
       [](const Row& r, X& x, const ast::Value& v, Sink& k) {
         const auto d = read_quantity(v, r.key, Dim::Length, k);
         if (d && !(*d > 0.0)) {
           k.error(v.where, fmt::format("`{}` is a length greater than 0, as in 10cm", r.key));
           return false;
         }
         if (d) x.formation.spacing_m = *d;
         return d.has_value();
       },
       [](const X& x) {
         const bool spaced = x.formation.kind == sim::FormationKind::Line || x.formation.kind == sim::FormationKind::Circle;
         return spaced && x.formation.spacing_m > 0.0 ? fmt::format("{} m", x.formation.spacing_m) : std::string();
       }},
      {"formation_at", "each robot's start pose (x, y, heading), one per robot, for `formation at`",
       [](const Row& r, X& x, const ast::Value& v, Sink& k) {
         static constexpr std::array kDims = {Dim::Length, Dim::Length, Dim::Angle};
         const auto rows = read_tuples(v, r.key, {kDims, 0, "[(20cm, 20cm, 90deg), (40cm, 20cm, 90deg)]"}, k);
         if (!rows) return false;
         x.formation.at.clear();
         for (const std::vector<double>& p : *rows) x.formation.at.push_back({p[0], p[1], p[2]});
         return true;
       },
       [](const X& x) {
         std::string t;
         if (x.formation.kind != sim::FormationKind::At) return t;
         for (const sim::Pose& p : x.formation.at)
           t += fmt::format("{}({} m, {} m, {} rad)", t.empty() ? "[" : ", ", p.x_m, p.y_m, p.heading_rad);
         return t.empty() ? t : t + "]";
       }},
      {"generations", "the experiment's generations (every network's), and GP's (the trees')",
       [](const Row& r, X& x, const ast::Value& v, Sink& k) {
         const auto n = read_count(v, r.key, 1, kIntMax, k);
         if (!n) return false;
         x.generations = static_cast<int>(*n);
         // And an algorithm's own generations where the experiment holds its settings (GP's).
         for (const AlgorithmOptions& a : algorithm_options())
           if (std::any* settings = a.held_by(x); settings != nullptr && a.has_key(r.key))
             (void)a.set(*settings, r.key, v, k);
         return true;
       },
       [](const X& x) { return std::to_string(x.experiment_generations()); }},
      // Resolved only when on, so that runs from before it keep their settings.
      {"stop_at_success", "end each run after the generation of its first success (`stop at success`)",
       [](const Row& r, X& x, const ast::Value& v, Sink& k) {
         const auto on = read_flag(v, r.key, k);
         if (!on) return false;
         if (*on && !x.success) {
           k.error(v.where, "`stop_at_success` needs the experiment's success test (`success when ...`)");
           return false;
         }
         x.stop_at_success = *on;
         return true;
       },
       [](const X& x) { return x.stop_at_success ? std::string("on") : std::string(); }},
      // Resolved only when not the default, so that runs from before it keep their settings.
      {"members_every", "store a front every this many generations, and at each run's last",
       &read_positive<&X::members_every>,
       [](const X& x) { return x.members_every == eval::kMembersEvery ? std::string() : count_text<&X::members_every>(x); }},
      // Resolved only when not the ES, so that runs from before it keep their settings.
      {"networks", "the algorithm that evolves the networks compared without `by` (`es`, `cmaes`)",
       [](const Row& r, X& x, const ast::Value& v, Sink& k) {
         const std::vector<std::string> names = algorithms_for(genome::GenomeKind::Vector);
         const auto i = read_word(v, r.key, names, k);
         if (!i) return false;
         x.networks = names[*i];
         if (const AlgorithmOptions* o = find_algorithm_options(x.networks)) o->settings_in(x);
         return true;
       },
       [](const X& x) { return x.networks == X::kDefaultNetworks ? std::string() : x.networks; }},
  };
  return table;
}

const ExperimentSetting* find_experiment_setting(std::string_view key) {
  return find_row(experiment_settings(), &ExperimentSetting::key, key);
}

}  // namespace esc::compiler
