#pragma once
// NSGA-II's options as scripts write them (`evolve nsga2(population 100, eta_crossover 20)`,
// `--set nsga2.mutation=0.05`; docs/language.md), and the check of its settings together.
#include <string>
#include <vector>

#include "runtime/evo/algorithm_options.hpp"
#include "runtime/evo/limits.hpp"
#include "runtime/evo/nsga2/nsga2.hpp"
#include "runtime/evo/optimizer.hpp"

namespace esc::evo {

[[nodiscard]] const std::vector<AlgorithmOption>& nsga2_options();

// NSGA-II's rows over any settings type with its fields (population, crossover,
// eta_crossover, eta_mutation, mutation, lower, upper): its own, and novelty search's, which
// breeds as NSGA-II does.
template <class S>
[[nodiscard]] std::vector<AlgorithmOption> nsga2_variation_options() {
  using F = OptionForm;
  using namespace option;
  static constexpr double kZero = 0.0;
  static constexpr double kOne = 1.0;
  static constexpr double kMaxEta = 1e6;
  static constexpr double kMaxBound = kMaxGeneBound;
  return {
      {"population", F::Number, "parents kept and children made per generation (even)", {},
       &whole<S, &S::population, 2, kNsga2MaxPopulation>, &whole_text<S, &S::population>},
      {"crossover", F::Number, "probability that a pair of tournament winners is crossed (SBX)", {},
       &real<S, &S::crossover, &kZero, false, &kOne, false>, &real_text<S, &S::crossover>},
      {"eta_crossover", F::Number, "SBX's distribution index: larger, children nearer their parents", {},
       &real<S, &S::eta_crossover, &kZero, false, &kMaxEta, false>, &real_text<S, &S::eta_crossover>},
      {"eta_mutation", F::Number, "polynomial mutation's distribution index", {},
       &real<S, &S::eta_mutation, &kZero, false, &kMaxEta, false>, &real_text<S, &S::eta_mutation>},
      {"mutation", F::Number, "probability that a gene mutates; 0: 1 / (the network's weights)", {},
       &real<S, &S::mutation, &kZero, false, &kOne, false>, &real_text<S, &S::mutation>},
      {"bounds", F::Range, "every weight stays in [LO, HI] (LO < HI, both within +-1e6)", {}, &bounds<S, &kMaxBound>,
       &bounds_text<S>},
  };
}

// Why NSGA-II cannot run with `settings` on `problem` (an odd population, ...), or "".
[[nodiscard]] std::string nsga2_problem(const Nsga2Settings& settings, const Problem& problem);

}  // namespace esc::evo
