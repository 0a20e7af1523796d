#include "compiler/experiment_settings.hpp"

#include <limits>

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
      {"robots", "robots of the experiment's body in the arena, each driven by its own copy of the controller",
       [](const Row& r, X& x, const ast::Value& v, Sink& k) {
         const auto n = read_count(v, r.key, 1, eval::kMaxRobots, k);
         if (n) x.robots = static_cast<int>(*n);
         return n.has_value();
       },
       [](const X& x) { return x.robots == 1 ? std::string() : count_text<&X::robots>(x); }},
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
