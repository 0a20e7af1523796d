#pragma once
// The report's figures of what NSGA-II, MAP-Elites and novelty search keep beside a run's
// best (store::StoredMembers), each of one controller's best run (its highest best fitness,
// the earliest on a tie), after its last generation:
// - a grid archive as a heatmap of the elites' fitness over the first two descriptors (one
//   row for one descriptor; with three, each square the best over the third);
// - a CVT archive over two descriptors as its Voronoi cells, drawn as a raster of the
//   nearest centroid (an elite's colour, grey where empty); over other numbers of
//   descriptors, the elites as points over the first two;
// - novelty search's archive as its behaviors over the first two descriptors;
// - a front (two objectives or more) as every finished run's final front over the first
//   two objectives.
// QD-score and coverage are metrics, drawn with the other metrics (figures.hpp).
#include <string>
#include <vector>

#include "runtime/report/figures.hpp"
#include "runtime/store/results_db.hpp"

namespace esc::report {

[[nodiscard]] std::vector<NamedFigure> member_figures(const store::StoredExperiment& e, const std::string& stem);

}  // namespace esc::report
