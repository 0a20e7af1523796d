#pragma once
// `esc report`: the stored results as one self-contained HTML page that works offline.
// Per experiment: fitness curves over generations per controller (mean over runs of the
// best and of the mean fitness, with a +-sd band across runs), box plots of the runs'
// best fitness, the statistics table (summary per controller, pairwise Welch and
// Mann-Whitney p-values), behavior-usage bars for symbolic controllers, and an animated
// replay of each controller's best evaluation (trajectory, IR readings, acting behavior).
// Chart.js and the page's script are embedded; the data is one JSON block in the page.
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "runtime/store/results_db.hpp"

namespace esc::report {

struct ReportOptions {
  // Replay steps embedded per controller (the first epochs of the best evaluation, whole
  // epochs where possible); the page stays light for the paper's 10 x 1000-step epochs.
  std::size_t max_replay_steps = 3000;
};

// The data block the page's script renders (exposed for tests).
[[nodiscard]] nlohmann::ordered_json report_data(const std::vector<store::StoredExperiment>& experiments,
                                                 const ReportOptions& options = {});

[[nodiscard]] std::string html_report(const std::vector<store::StoredExperiment>& experiments,
                                      const ReportOptions& options = {});

}  // namespace esc::report
