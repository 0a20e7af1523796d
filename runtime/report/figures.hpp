#pragma once
// The figures `esc report` writes as SVG files (DIR/figures/) and shows in the report:
// - per experiment or study condition, the paper's Figure 1: for each controller the
//   maximum and the mean over runs of the best fitness of each generation, and the best
//   so far (mean over runs of each run's best up to that generation); a box plot of the
//   runs' best fitness; the paper's Figure 2 per controller that chooses behaviors
//   (usage_figure.hpp); and what the optimizers reported per generation (CMA-ES's sigma),
//   where they reported anything;
// - per study, box plots of each controller's runs across the conditions (one panel per
//   controller), and for each sweep the final best fitness against the swept value (mean
//   and sd over runs, one line per controller; a categorical axis when the values are not
//   numbers in one unit).
#include <string>
#include <vector>

#include "runtime/store/results_db.hpp"

namespace esc::report {

struct NamedFigure {
  std::string file;    // its name in figures/ (`loophole-no_inertia-fitness.svg`)
  std::string title;
  std::string svg;
};

// `stem` starts each file's name.
[[nodiscard]] std::vector<NamedFigure> experiment_figures(const store::StoredExperiment& e, const std::string& stem);

// The study's own figures; `conditions` in the study's order.
[[nodiscard]] std::vector<NamedFigure> study_figures(const std::vector<const store::StoredExperiment*>& conditions,
                                                     const std::string& stem);

}  // namespace esc::report
