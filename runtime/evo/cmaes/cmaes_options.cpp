#include "runtime/evo/cmaes/cmaes_options.hpp"

#include <string_view>

#include "runtime/evo/cmaes/cmaes.hpp"
#include "runtime/evo/limits.hpp"

namespace esc::evo {

namespace {

using S = CmaesSettings;
using F = OptionForm;
using namespace option;

constexpr double kZero = 0.0;
constexpr double kOne = 1.0;

}  // namespace

const std::vector<AlgorithmOption>& cmaes_options() {
  static const std::vector<AlgorithmOption> table = {
      {"lambda", F::Number, "candidates per generation; 0: 4 + floor(3 ln n)", {}, &whole<S, &S::lambda, 0, kCmaesMaxLambda>,
       &whole_text<S, &S::lambda>},
      {"mu", F::Number, "parents recombined, at most lambda / 2; 0: lambda / 2", {}, &whole<S, &S::mu, 0, kCmaesMaxLambda / 2>,
       &whole_text<S, &S::mu>},
      {"sigma", F::Number, "initial step size, a fraction of HI - LO (> 0, at most 1000)", {},
       &real<S, &S::sigma, &kZero, true, &kMaxStepSize, false>, &real_text<S, &S::sigma>},
      {"bounds", F::Range, "every weight stays in [LO, HI] (LO < HI, both within +-1e6)", {},
       &bounds<S, &kMaxGeneBound>, &bounds_text<S>},
      {"covariance", F::Word,
       "a full covariance matrix, or its diagonal only (sep-CMA-ES, for networks of hundreds of weights)",
       {"full", "separable"}, &two_words<S, &S::separable>,
       [](const std::any& s) { return std::string(std::any_cast<const S&>(s).separable ? "separable" : "full"); }},
      {"restarts", F::Number, "IPOP: restarts with the population doubled after a stop; 0: none", {},
       &whole<S, &S::restarts, 0, kCmaesMaxRestarts>, &whole_text<S, &S::restarts>},
      {"stop_sigma", F::Number, "stop when every coordinate's sd is below this fraction of HI - LO (below 1); 0: never", {},
       &real<S, &S::stop_sigma, &kZero, false, &kOne, true>, &real_text<S, &S::stop_sigma>},
      {"stop_condition", F::Number, "stop when the covariance's condition number exceeds this (at most 1e16)", {},
       &real<S, &S::stop_condition, &kOne, true, &kCmaesMaxCondition, false>, &real_text<S, &S::stop_condition>},
      {"stop_flat", F::Number, "stop after this many generations in a row whose best fitness equals the fitness ranked "
       "floor(0.1 + lambda / 4) behind it (a flat fitness); 0: never", {},
       &whole<S, &S::stop_flat, 0, 1000000000>, &whole_text<S, &S::stop_flat>},
  };
  return table;
}

std::string cmaes_problem(const CmaesSettings& settings, std::size_t genome_size) {
  return rejection([&] { (void)Cmaes(settings, genome_size); }, "CMA-ES: ");
}

}  // namespace esc::evo
