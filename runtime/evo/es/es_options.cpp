#include "runtime/evo/es/es_options.hpp"

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "runtime/evo/limits.hpp"

namespace esc::evo {

namespace {

using S = EsSettings;
using F = OptionForm;
using namespace option;

const std::vector<std::string> kSelections = {"comma", "plus"};
const std::vector<std::string> kRecombinations = {"intermediate", "discrete", "no_recombination"};
const std::vector<std::string> kStepSizes = {"one_sigma", "self_adaptive"};

// `bounds [LO, HI]` of the weights, refused in the ES's historic words, which name the bounds
// themselves (tests/bad/empty_bounds.esc).
OptionRefusal gene_bounds(std::any& s, const OptionValue& v) {
  if (std::abs(v.lo) > kMaxGeneBound || std::abs(v.hi) > kMaxGeneBound)
    return {fmt::format("bounds must lie within [-{0}, {0}], found [{1}, {2}]", number(kMaxGeneBound), number(v.lo),
                        number(v.hi)),
            "beyond that the steps and the networks' sums lose their precision and can overflow; scale the inputs "
            "instead",
            true};
  if (!(v.lo < v.hi))
    return {fmt::format("empty bounds: the lower bound ({}) must be below the upper ({})", number(v.lo), number(v.hi)),
            "", true};
  std::any_cast<S&>(s).lower = v.lo;
  std::any_cast<S&>(s).upper = v.hi;
  return {};
}

}  // namespace

const std::vector<AlgorithmOption>& es_options() {
  static const std::vector<AlgorithmOption> table = {
      {"mu", F::Count, "parents", {}, &count<S, &S::mu>, &count_text<S, &S::mu>, 1},
      {"lambda", F::Count, "offspring per generation", {}, &count<S, &S::lambda>, &count_text<S, &S::lambda>, 1},
      {"selection", F::Word, "the parents from the offspring only, or from parents and offspring", kSelections,
       &choice<S, &S::selection>, &choice_text<S, &S::selection, kSelections>},
      {"recombination", F::Word, "of the two parents of each offspring", kRecombinations,
       &choice<S, &S::recombination>, &choice_text<S, &S::recombination, kRecombinations>},
      {"step_sizes", F::Word, "one step size per individual, or one per gene", kStepSizes,
       &choice<S, &S::step_sizes>, &choice_text<S, &S::step_sizes, kStepSizes>},
      {"bounds", F::Range, "genes stay in [LO, HI] (LO < HI, both within +-1e6)", {}, &gene_bounds, &bounds_text<S>},
      {"sigma", F::Number, "initial step size, a fraction of HI - LO (> 0, at most 1000)", {},
       &signed_real<S, &S::initial_sigma, Sign::Positive, &kMaxStepSize>, &signed_real_text<S, &S::initial_sigma>},
      {"min_sigma", F::Number, "floor of the step sizes (>= 0, at most HI - LO)", {},
       &signed_real<S, &S::min_sigma, Sign::NonNegative>, &signed_real_text<S, &S::min_sigma>},
      {"generations", F::Count, "generations; also `for N generations`", {}, nullptr, nullptr, 1, true},
  };
  return table;
}

OptionRefusal es_conflict(const S& s) {
  if (s.selection == Selection::Comma && s.lambda < s.mu)
    return {fmt::format("comma selection needs `lambda` >= `mu`, found mu {} and lambda {}", s.mu, s.lambda),
            "raise `lambda`, or use `plus` selection", true};
  if (s.min_sigma > s.upper - s.lower)
    return {fmt::format("`min_sigma` ({}) is wider than the bounds (HI - LO = {})", number(s.min_sigma),
                        number(s.upper - s.lower)),
            "every step would cross the whole interval: lower `min_sigma`", true};
  return {};
}

}  // namespace esc::evo
