#include "runtime/evo/neat/neat_options.hpp"

#include <any>
#include <string_view>

#include <fmt/format.h>

namespace esc::evo {

namespace {

using S = NeatSettings;
using F = OptionForm;
using namespace option;
namespace gg = genome::graph;

constexpr double kZero = 0.0;
constexpr double kOne = 1.0;
constexpr double kMaxCoefficient = 1000.0;
constexpr double kMaxThreshold = 1e6;
constexpr int kMaxPopulation = 1000000;
constexpr int kMaxCount = 1000000000;
constexpr std::size_t kMaxPorts = 100000;   // inputs or outputs of one network
constexpr int kMaxStartHidden = 1000;

// A probability in [0, 1].
template <double S::*Field>
AlgorithmOption probability(std::string_view key, std::string_view summary) {
  return {key, F::Number, summary, {}, &real<S, Field, &kZero, false, &kOne, false>, &real_text<S, Field>};
}

// A coefficient in [0, 1000].
template <double S::*Field>
AlgorithmOption coefficient(std::string_view key, std::string_view summary) {
  return {key, F::Number, summary, {}, &real<S, Field, &kZero, false, &kMaxCoefficient, false>, &real_text<S, Field>};
}

// A positive number, at most 1000.
template <double S::*Field>
AlgorithmOption positive(std::string_view key, std::string_view summary) {
  return {key, F::Number, summary, {}, &real<S, Field, &kZero, true, &kMaxCoefficient, false>, &real_text<S, Field>};
}

OptionRefusal set_activation(std::any& s, const OptionValue& v) {
  std::any_cast<S&>(s).activation = static_cast<gg::Activation>(v.word);
  return {};
}

std::string activation_text(const std::any& s) {
  return std::string(gg::activation_name(std::any_cast<const S&>(s).activation));
}

OptionRefusal set_score(std::any& s, const OptionValue& v) {
  std::any_cast<S&>(s).score = static_cast<NeatScore>(v.word);
  return {};
}

std::string score_text(const std::any& s) {
  return std::any_cast<const S&>(s).score == NeatScore::Novelty ? "novelty" : "fitness";
}

}  // namespace

const std::vector<AlgorithmOption>& neat_options() {
  static const std::vector<AlgorithmOption> table = {
      {"population",
       F::Number,
       "networks per generation",
       {},
       &whole<S, &S::population, 2, kMaxPopulation>,
       &whole_text<S, &S::population>},
      coefficient<&S::excess_coeff>("excess_coeff", "c1: weight of excess links in the compatibility distance"),
      coefficient<&S::disjoint_coeff>("disjoint_coeff", "c2: weight of disjoint links in the compatibility distance"),
      coefficient<&S::weight_coeff>("weight_coeff", "c3: weight of the matching links' mean weight difference"),
      {"threshold",
       F::Number,
       "delta_t: a network joins the first species closer than this",
       {},
       &real<S, &S::threshold, &kZero, true, &kMaxThreshold, false>,
       &real_text<S, &S::threshold>},
      {"target_species",
       F::Number,
       "steer the threshold towards this many species; 0: a fixed threshold",
       {},
       &whole<S, &S::target_species, 0, kMaxPopulation>,
       &whole_text<S, &S::target_species>},
      positive<&S::threshold_step>("threshold_step", "how far the threshold moves each generation when steered"),
      {"dropoff_age",
       F::Number,
       "a species whose best has not risen for this many generations breeds at 1%",
       {},
       &whole<S, &S::dropoff_age, 1, kMaxCount>,
       &whole_text<S, &S::dropoff_age>},
      {"survival_thresh",
       F::Number,
       "the best fraction of each species that breeds (in (0, 1])",
       {},
       &real<S, &S::survival_thresh, &kZero, true, &kOne, false>,
       &real_text<S, &S::survival_thresh>},
      {"elitism",
       F::Number,
       "a species with more offspring than this keeps its champion unchanged",
       {},
       &whole<S, &S::elitism, 0, kMaxPopulation>,
       &whole_text<S, &S::elitism>},
      probability<&S::mutate_only_prob>("mutate_only_prob", "offspring made by mutation alone"),
      probability<&S::mate_only_prob>("mate_only_prob", "offspring of crossover left unmutated"),
      probability<&S::interspecies_mate_rate>("interspecies_mate_rate", "crossovers with another species' champion"),
      probability<&S::mate_multipoint_prob>(
          "mate_multipoint_prob", "crossovers taking each matching link from one parent; the rest average them"),
      probability<&S::weight_mut_prob>("weight_mut_prob", "mutations that change the weights"),
      positive<&S::weight_mut_power>("weight_mut_power", "a weight changes by at most this"),
      probability<&S::toggle_enable_prob>("toggle_enable_prob", "mutations that switch a link on or off"),
      probability<&S::reenable_prob>("reenable_prob", "mutations that switch the first disabled link back on"),
      probability<&S::add_node_prob>("add_node_prob", "mutations that split a link with a new node"),
      probability<&S::add_link_prob>("add_link_prob", "mutations that add a link"),
      probability<&S::recur_only_prob>("recur_only_prob", "added links that must be recurrent; 0: a feed-forward net"),
      {"newlink_tries",
       F::Number,
       "pairs of nodes tried before add_link gives up",
       {},
       &whole<S, &S::newlink_tries, 1, kMaxPopulation>,
       &whole_text<S, &S::newlink_tries>},
      positive<&S::new_link_weight>("new_link_weight", "a new link's weight is drawn in [-this, this]"),
      {"activation",
       F::Word,
       "of every hidden and output node (neat_sigmoid: 1 / (1 + exp(-4.924273 x)))",
       {"neat_sigmoid", "tanh", "sigmoid", "linear"},
       &set_activation,
       &activation_text},
      {"start_hidden",
       F::Number,
       "hidden nodes of the start network between its sensors and outputs; 0: the minimal start",
       {},
       &whole<S, &S::start_hidden, 0, kMaxStartHidden>,
       &whole_text<S, &S::start_hidden>},
      {"score",
       F::Word,
       "what reproduction ranks: the fitness, or the novelty of the descriptors (Lehman & Stanley)",
       {"fitness", "novelty"},
       &set_score,
       &score_text},
      {"novelty_k",
       F::Number,
       "score novelty: nearest neighbours a novelty is the mean distance to",
       {},
       &whole<S, &S::novelty_k, 1, kMaxPopulation>,
       &whole_text<S, &S::novelty_k>},
      {"novelty_threshold",
       F::Number,
       "score novelty: initial novelty a network needs to enter the archive (descriptors scaled to [0, 1])",
       {},
       &real<S, &S::novelty_threshold, &kZero, true, &kMaxThreshold, false>,
       &real_text<S, &S::novelty_threshold>},
  };
  return table;
}

std::string neat_problem(const NeatSettings& settings, std::size_t inputs, std::size_t outputs) {
  if (inputs == 0 || outputs == 0)
    return fmt::format("a network needs inputs and outputs, found {} and {}", inputs, outputs);
  if (inputs > kMaxPorts || outputs > kMaxPorts)
    return fmt::format("at most {} inputs and {} outputs, found {} and {}", kMaxPorts, kMaxPorts, inputs, outputs);
  // Every row's check, on a copy: settings made in code pass the table's ranges too.
  std::any copy = settings;
  for (const AlgorithmOption& o : neat_options()) {
    if (o.form != OptionForm::Number) continue;
    OptionValue v;
    const std::string text = o.text(copy);
    v.number = std::stod(text);
    if (OptionRefusal why = o.set(copy, v); !why.empty()) return fmt::format("{} {}", o.key, why.message);
  }
  return {};
}

}  // namespace esc::evo
