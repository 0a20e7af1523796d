#include "runtime/evo/map_elites/map_elites_options.hpp"

#include "runtime/evo/limits.hpp"
#include "runtime/evo/map_elites/map_elites_optimizer.hpp"

namespace esc::evo {

namespace {

using S = MapElitesRunSettings;
using F = OptionForm;
using namespace option;

constexpr double kZero = 0.0;
constexpr double kOne = 1.0;
constexpr int kMaxBatch = static_cast<int>(qd::kMaxMapElitesBatch);

// The rows both variants share: variation, batch sizes and the box.
std::vector<AlgorithmOption> common() {
  return {
      {"batch", F::Number, "children per generation, each from two elites drawn uniformly", {},
       &whole<S, &S::batch, 1, kMaxBatch>, &whole_text<S, &S::batch>},
      {"initial", F::Number, "genomes drawn uniformly in the box in the first generation", {},
       &whole<S, &S::initial, 1, kMaxBatch>, &whole_text<S, &S::initial>},
      {"sigma_iso", F::Number, "Iso+LineDD's isotropic spread, a fraction of HI - LO", {},
       &real<S, &S::sigma_iso, &kZero, false, &kOne, false>, &real_text<S, &S::sigma_iso>},
      {"sigma_line", F::Number, "Iso+LineDD's spread along the line between the two elites", {},
       &real<S, &S::sigma_line, &kZero, false, &kMaxStepSize, false>, &real_text<S, &S::sigma_line>},
      {"bounds", F::Range, "every weight stays in [LO, HI] (LO < HI, both within +-1e6)", {},
       &bounds<S, &kMaxGeneBound>, &bounds_text<S>},
  };
}

}  // namespace

const std::vector<AlgorithmOption>& map_elites_options() {
  static const std::vector<AlgorithmOption> table = [] {
    std::vector<AlgorithmOption> t{{"bins", F::Number, "cells per descriptor of the grid (1 to 3 descriptors)", {},
                                    &whole<S, &S::bins, 1, 100'000'000>, &whole_text<S, &S::bins>}};
    for (AlgorithmOption& o : common()) t.push_back(std::move(o));
    return t;
  }();
  return table;
}

const std::vector<AlgorithmOption>& cvt_map_elites_options() {
  static const std::vector<AlgorithmOption> table = [] {
    std::vector<AlgorithmOption> t{
        {"cells", F::Number, "centroids of the CVT of the descriptor space", {}, &whole<S, &S::cells, 1, 100'000'000>,
         &whole_text<S, &S::cells>},
        {"samples", F::Number, "uniform points the CVT's k-means runs on (at least `cells`)", {},
         &whole<S, &S::samples, 1, static_cast<int>(qd::kMaxCvtSamples)>, &whole_text<S, &S::samples>}};
    for (AlgorithmOption& o : common()) t.push_back(std::move(o));
    return t;
  }();
  return table;
}

}  // namespace esc::evo
