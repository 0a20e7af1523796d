#pragma once
// `esc report`: the stored results as one self-contained HTML page that works offline.
// Per experiment: fitness curves over generations per controller (mean over runs of the
// best and of the mean fitness, with a +-sd band across runs), box plots of the runs'
// best fitness, the statistics table (summary per controller, pairwise Welch and
// Mann-Whitney p-values), behavior-usage bars for symbolic controllers, and an animated
// replay of each controller's best evaluation (trajectory, IR readings, acting behavior).
// Per study: the table of conditions by controllers, its family of comparisons
// (study_table.hpp), and its figures. The SVG figures (figures.hpp) are shown in the page
// and returned to be written as files. Chart.js and the page's script are embedded; the
// data is one JSON block in the page. Several run directories make one report.
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "runtime/report/figures.hpp"
#include "runtime/store/results_db.hpp"

namespace esc::report {

struct ReportOptions {
  // Replay steps embedded per controller (the first epochs of the best evaluation, whole
  // epochs where possible); the page stays light for the paper's 10 x 1000-step epochs.
  std::size_t max_replay_steps = 3000;
};

struct Report {
  nlohmann::ordered_json data;       // the data block the page's script renders
  std::string html;
  std::vector<NamedFigure> figures;  // every figure the page shows, file names unique
};

[[nodiscard]] Report make_report(const std::vector<store::StoredDirectory>& directories,
                                 const ReportOptions& options = {});

// The report of one directory's experiments (its path unknown).
[[nodiscard]] nlohmann::ordered_json report_data(const std::vector<store::StoredExperiment>& experiments,
                                                 const ReportOptions& options = {});
[[nodiscard]] std::string html_report(const std::vector<store::StoredExperiment>& experiments,
                                      const ReportOptions& options = {});

}  // namespace esc::report
