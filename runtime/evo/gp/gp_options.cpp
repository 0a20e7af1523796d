#include "runtime/evo/gp/gp_options.hpp"

#include <string_view>

#include <fmt/format.h>

#include "runtime/genome/tree/primitive_set.hpp"

namespace esc::evo::gp {

namespace {

using S = GpSettings;
using F = OptionForm;
using namespace option;

template <auto Field>
constexpr auto probability = &signed_real<S, Field, Sign::Probability>;

// `init_depth [LO, HI]`: whole numbers the compiler checked (at least 1), LO <= HI.
OptionRefusal depths(std::any& s, const OptionValue& v) {
  const int lo = static_cast<int>(v.lo), hi = static_cast<int>(v.hi);
  if (hi < lo)
    return {fmt::format("`init_depth [{}, {}]` is empty: the first depth must not exceed the second", lo, hi), "",
            true};
  std::any_cast<S&>(s).init_min_depth = lo;
  std::any_cast<S&>(s).init_max_depth = hi;
  return {};
}

std::string depths_text(const std::any& s) {
  const S& x = std::any_cast<const S&>(s);
  return fmt::format("[{}, {}]", x.init_min_depth, x.init_max_depth);
}

// A single tree controller's set (a Number terminal), for settings no tree is compared with.
const genome::tree::PrimitiveSet& neutral_set() {
  static const genome::tree::PrimitiveSet set({genome::tree::prim::constant(genome::tree::Type::Number, 0.0)},
                                              genome::tree::Type::Number);
  return set;
}

}  // namespace

const std::vector<AlgorithmOption>& gp_options() {
  static const std::vector<AlgorithmOption> table = {
      {"population", F::Count, "trees per generation, all evaluated every generation", {}, &count<S, &S::population>,
       &count_text<S, &S::population>, 1},
      {"generations", F::Count, "generations; also `for N generations`", {}, &count<S, &S::generations>,
       &count_text<S, &S::generations>, 1},
      {"tournament", F::Count, "tournament size; of equally fit contestants the smaller tree wins", {},
       &count<S, &S::tournament>, &count_text<S, &S::tournament>, 1},
      {"elitism", F::Count, "best trees copied unchanged into the next generation (0 .. population)", {},
       &count<S, &S::elitism>, &count_text<S, &S::elitism>, 0},
      {"crossover", F::Number, "probability of subtree crossover, per offspring", {}, probability<&S::crossover>,
       &signed_real_text<S, &S::crossover>},
      {"subtree_mutation", F::Number, "probability of subtree mutation", {}, probability<&S::subtree_mutation>,
       &signed_real_text<S, &S::subtree_mutation>},
      {"point_mutation", F::Number, "probability of point mutation", {}, probability<&S::point_mutation>,
       &signed_real_text<S, &S::point_mutation>},
      {"hoist_mutation", F::Number, "probability of hoist mutation; what is left is reproduction (a copy)", {},
       probability<&S::hoist_mutation>, &signed_real_text<S, &S::hoist_mutation>},
      {"max_depth", F::Count, "levels from the root to the deepest leaf (a terminal is 1; at most 40)", {},
       &count<S, &S::max_depth>, &count_text<S, &S::max_depth>, 1},
      {"max_size", F::Count, "nodes", {}, &count<S, &S::max_size>, &count_text<S, &S::max_size>, 1},
      {"init_depth", F::CountRange, "depths of the ramped half-and-half initial population", {}, &depths, &depths_text,
       1},
      {"mutation_depth", F::Count, "depth of the subtrees grown by subtree mutation", {},
       &count<S, &S::mutation_depth>, &count_text<S, &S::mutation_depth>, 1},
      {"internal_bias", F::Number, "crossover picks an internal node this often", {}, probability<&S::internal_bias>,
       &signed_real_text<S, &S::internal_bias>},
      {"erc_sigma", F::Number, "point mutation moves an ERC by N(0, X (HI - LO)) (at most 1000)", {},
       &signed_real<S, &S::erc_sigma, Sign::NonNegative, &S::kMaxErcSigma>, &signed_real_text<S, &S::erc_sigma>},
  };
  return table;
}

std::string gp_problem(const GpSettings& settings, const genome::tree::PrimitiveSet* set) {
  return rejection([&] { (void)GeneticProgramming(settings, set != nullptr ? *set : neutral_set()); },
                   "genetic programming: ");
}

}  // namespace esc::evo::gp
