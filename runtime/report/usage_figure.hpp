#pragma once
// The paper's Figure 2 as an SVG file (DIR/figures/), beside the report's interactive chart
// of the same lines (report.js): for each controller that chooses actions or behaviors, how
// often each was called per 10,000 steps in each generation's best evaluation, as
// generations go by, mean over the finished runs with a band of ± one sd. The behaviors of
// libraries marked `useless` get a panel of their own, and a panel that would hold more than
// 8 lines has one per library instead (its members' calls summed), as sensitivity.esc's 24
// behaviors need.
#include <string>
#include <vector>

#include "runtime/report/figures.hpp"
#include "runtime/store/results_db.hpp"

namespace esc::report {

// A line of the figure: one choice, or a library's choices summed.
struct UsageLine {
  std::string label;
  std::vector<std::size_t> indices;   // into the controller's choices
};

struct UsagePanel {
  std::string title;                  // "behaviors", or "useful behaviors" / "useless behaviors"
  bool by_library = false;            // its lines are libraries, not choices
  std::vector<UsageLine> lines;
};

// The panels and lines of controller `c`'s figure; the report's chart draws the same ones.
// A database that kept the names alone (no libraries, no marks) draws them as useful.
[[nodiscard]] std::vector<UsagePanel> usage_panels(const store::StoredController& c);

// One figure per controller with usage stored (`STEM-usage-CONTROLLER.svg`); none for a
// classical controller or a database written before usage was kept per generation.
[[nodiscard]] std::vector<NamedFigure> usage_figures(const store::StoredExperiment& e, const std::string& stem);

}  // namespace esc::report
