#include "runtime/evo/novelty/novelty_options.hpp"

#include "runtime/evo/limits.hpp"
#include "runtime/evo/novelty/novelty_optimizer.hpp"
#include "runtime/evo/nsga2/nsga2_options.hpp"

namespace esc::evo {

namespace {

using S = NoveltyRunSettings;
using F = OptionForm;
using namespace option;

constexpr double kZero = 0.0;
constexpr double kOne = 1.0;

}  // namespace

const std::vector<AlgorithmOption>& novelty_options() {
  static const std::vector<AlgorithmOption> table = [] {
    std::vector<AlgorithmOption> t = {
      {"objectives", F::Word, "novelty alone, or novelty and the fitness as two NSGA-II objectives",
       {"novelty", "novelty_fitness"}, &two_words<S, &S::with_fitness>,
       [](const std::any& s) {
         return std::string(std::any_cast<const S&>(s).with_fitness ? "novelty_fitness" : "novelty");
       }},
      {"k", F::Number, "nearest neighbours a novelty is the mean distance to", {}, &whole<S, &S::k, 1, 100000>,
       &whole_text<S, &S::k>},
      {"archive", F::Word, "candidates enter the archive above the threshold, which adapts, or at random",
       {"adaptive", "random"}, &two_words<S, &S::random_archive>,
       [](const std::any& s) { return std::string(std::any_cast<const S&>(s).random_archive ? "random" : "adaptive"); }},
      {"threshold", F::Number, "initial novelty a candidate needs to enter the archive (descriptors scaled to [0, 1])",
       {}, &real<S, &S::threshold, &kZero, true, &kMaxGeneBound, false>, &real_text<S, &S::threshold>},
      {"random_probability", F::Number, "probability that a candidate enters the archive (archive random)", {},
       &real<S, &S::random_probability, &kZero, false, &kOne, false>, &real_text<S, &S::random_probability>},
    };
    for (AlgorithmOption& o : nsga2_variation_options<S>()) t.push_back(std::move(o));
    return t;
  }();
  return table;
}

}  // namespace esc::evo
