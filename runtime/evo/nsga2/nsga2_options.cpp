#include "runtime/evo/nsga2/nsga2_options.hpp"

#include <stdexcept>

#include "runtime/evo/limits.hpp"

namespace esc::evo {

namespace {

using S = Nsga2Settings;
using F = OptionForm;
using namespace option;

constexpr double kZero = 0.0;
constexpr double kOne = 1.0;
constexpr double kMaxEta = 1e6;

}  // namespace

const std::vector<AlgorithmOption>& nsga2_options() {
  static const std::vector<AlgorithmOption> table = {
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
      {"bounds", F::Range, "every weight stays in [LO, HI] (LO < HI, both within +-1e6)", {},
       &bounds<S, &kMaxGeneBound>, &bounds_text<S>},
  };
  return table;
}

std::string nsga2_problem(const Nsga2Settings& settings, const Problem& /*problem*/) {
  try {
    check_nsga2_settings(settings);
  } catch (const std::invalid_argument& e) {
    std::string m = e.what();
    constexpr std::string_view prefix = "NSGA-II: ";
    if (m.starts_with(prefix)) m.erase(0, prefix.size());
    return m;
  }
  return {};
}

}  // namespace esc::evo
