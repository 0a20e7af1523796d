#pragma once
// The network NEAT evolved as each run's best, drawn (DIR/figures/): sensors in the left
// column, outputs in the right one, every hidden node in the column of its depth (the
// longest chain of enabled links from a sensor to it), each enabled link a line whose width
// grows with |weight|, blue when positive and red when negative (a recurrent link, drawn
// leftwards, dashed), a disabled one not drawn. What `--table topology` lists, as a picture.
#include <string>
#include <vector>

#include "runtime/genome/graph/graph.hpp"
#include "runtime/report/figures.hpp"
#include "runtime/store/results_db.hpp"

namespace esc::report {

// One graph's drawing, titled `title`.
[[nodiscard]] std::string network_svg(const genome::graph::Graph& g, const std::string& title);

// One figure per finished run of every NEAT controller (`STEM-network-CONTROLLER-run-NN.svg`);
// none for other controllers.
[[nodiscard]] std::vector<NamedFigure> network_figures(const store::StoredExperiment& e, const std::string& stem);

}  // namespace esc::report
