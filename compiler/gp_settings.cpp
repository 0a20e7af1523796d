#include "compiler/gp_settings.hpp"

#include <limits>
#include <stdexcept>

#include <fmt/format.h>

#include "compiler/names.hpp"
#include "compiler/quantities.hpp"
#include "compiler/setting_keys.hpp"
#include "compiler/setting_values.hpp"

namespace esc::compiler {

namespace {

using S = evo::gp::GpSettings;
using Shape = OptionShape;

// A single tree controller's set (a Number terminal) for settings no tree is compared with.
const genome::tree::PrimitiveSet& neutral_set() {
  static const genome::tree::PrimitiveSet set({genome::tree::prim::constant(genome::tree::Type::Number, 0.0)},
                                         genome::tree::Type::Number);
  return set;
}

std::string without_prefix(std::string message) {
  constexpr std::string_view prefix = "genetic programming: ";
  if (message.rfind(prefix, 0) == 0) message.erase(0, prefix.size());
  return message;
}

template <auto Field>
constexpr auto probability = &read_real<S, Field, RealRange::Probability>;

// `init_depth [LO, HI]`: whole numbers of at least 1, LO <= HI.
bool read_depths(const GpOption& o, S& s, const ast::Value& v, Sink& sink) {
  if (!read_range(v, o.key, "[2, 6]", sink)) return false;
  ast::Value lo = v, hi = v;
  lo.kind = hi.kind = ast::Value::Kind::Quantity;
  hi.q = v.hi;
  constexpr long long kIntMax = std::numeric_limits<int>::max();
  const auto first = read_count(lo, o.key, 1, kIntMax, sink), last = read_count(hi, o.key, 1, kIntMax, sink);
  if (!first || !last) return false;
  if (*last < *first) {
    sink.error(v.where, fmt::format("`init_depth [{}, {}]` is empty: the first depth must not exceed the second",
                                    *first, *last));
    return false;
  }
  s.init_min_depth = static_cast<int>(*first);
  s.init_max_depth = static_cast<int>(*last);
  return true;
}

std::string depths(const GpOption&, const S& s) { return fmt::format("[{}, {}]", s.init_min_depth, s.init_max_depth); }

}  // namespace

const std::vector<GpOption>& gp_options() {
  static const std::vector<GpOption> table = {
      {"population", Shape::Value, "trees per generation, all evaluated every generation",
       &read_whole<S, &S::population, 1>, &whole_text<S, &S::population>},
      {"generations", Shape::Value, "generations; also `for N generations`", &read_whole<S, &S::generations, 1>,
       &whole_text<S, &S::generations>},
      {"tournament", Shape::Value, "tournament size; of equally fit contestants the smaller tree wins",
       &read_whole<S, &S::tournament, 1>, &whole_text<S, &S::tournament>},
      {"elitism", Shape::Value, "best trees copied unchanged into the next generation (0 .. population)",
       &read_whole<S, &S::elitism, 0>, &whole_text<S, &S::elitism>},
      {"crossover", Shape::Value, "probability of subtree crossover, per offspring", probability<&S::crossover>,
       &real_text<S, &S::crossover>},
      {"subtree_mutation", Shape::Value, "probability of subtree mutation", probability<&S::subtree_mutation>,
       &real_text<S, &S::subtree_mutation>},
      {"point_mutation", Shape::Value, "probability of point mutation", probability<&S::point_mutation>,
       &real_text<S, &S::point_mutation>},
      {"hoist_mutation", Shape::Value, "probability of hoist mutation; what is left is reproduction (a copy)",
       probability<&S::hoist_mutation>, &real_text<S, &S::hoist_mutation>},
      {"max_depth", Shape::Value, "levels from the root to the deepest leaf (a terminal is 1; at most 40)",
       &read_whole<S, &S::max_depth, 1>, &whole_text<S, &S::max_depth>},
      {"max_size", Shape::Value, "nodes", &read_whole<S, &S::max_size, 1>, &whole_text<S, &S::max_size>},
      {"init_depth", Shape::Range, "depths of the ramped half-and-half initial population", &read_depths, &depths},
      {"mutation_depth", Shape::Value, "depth of the subtrees grown by subtree mutation",
       &read_whole<S, &S::mutation_depth, 1>, &whole_text<S, &S::mutation_depth>},
      {"internal_bias", Shape::Value, "crossover picks an internal node this often", probability<&S::internal_bias>,
       &real_text<S, &S::internal_bias>},
      {"erc_sigma", Shape::Value, "point mutation moves an ERC by N(0, X (HI - LO)) (at most 1000)",
       &read_real<S, &S::erc_sigma, RealRange::NonNegative, &S::kMaxErcSigma>, &real_text<S, &S::erc_sigma>},
  };
  return table;
}

void lower_gp_item(const ast::ExpItem& item, eval::ExperimentSpec& x, Sink& sink) {
  S s = x.gp.value_or(S{});
  read_options(item, "gp", "GP", gp_options(), s, sink);
  x.gp = s;
}

std::string check_gp(const eval::ExperimentSpec& spec) {
  if (!spec.gp) return {};
  bool any_tree = false;
  for (const control::ControllerSpec& c : spec.controllers) {
    if (!c.is_tree()) continue;
    any_tree = true;
    try {
      (void)evo::gp::GeneticProgramming(*spec.gp, *c.primitives);
    } catch (const std::invalid_argument& e) {
      return fmt::format("impossible GP settings for tree controller `{}`: {}", c.name, without_prefix(e.what()));
    }
  }
  if (!any_tree) {
    try {
      (void)evo::gp::GeneticProgramming(*spec.gp, neutral_set());
    } catch (const std::invalid_argument& e) {
      return fmt::format("impossible GP settings: {}", without_prefix(e.what()));
    }
  }
  return {};
}

void resolve_gp_settings(eval::ExperimentSpec& spec) {
  auto& r = spec.resolved_settings;
  for (auto it = r.begin(); it != r.end();) it = it->first.starts_with(kGpGroup) ? r.erase(it) : std::next(it);
  if (!spec.gp) return;
  for (const GpOption& o : gp_options()) r[std::string(kGpGroup).append(o.key)] = o.text(o, *spec.gp);
}

}  // namespace esc::compiler
