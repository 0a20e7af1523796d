#pragma once
// Progress of a campaign. On a terminal: one live line redrawn in place (a bar, the
// controller, run and generation, best and mean fitness of the generation, evaluations
// per second and the estimated time left), cut to the terminal's width so that it never
// wraps, and one permanent line per finished run. Runs are numbered from 1, generations
// from 0, as in every other output.
// Rates and time left are those of the last round: every run advancing together.
// Otherwise (a pipe, a log file): one plain line per generation.
#include <chrono>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "app/events.hpp"

namespace esc::cli {

class ProgressPrinter final : public app::Progress {
 public:
  // `already_done`: generations finished before this process started (a resumed run).
  ProgressPrinter(const eval::ExperimentSpec& spec, eval::CampaignListener& next, bool live,
                  std::int64_t already_done = 0);

  void round_progress(const eval::RoundProgress& progress) override;
  void round_evaluated(const eval::RoundStats& round) override;
  void generation_done(const control::ControllerSpec& controller, int run,
                       const eval::GenerationStats& stats) override;
  void checkpoint(const control::ControllerSpec& controller, const eval::RunState& state) override;
  void run_done(const control::ControllerSpec& controller, const eval::RunResult& run) override;

  // Ends the live line (call before printing anything else).
  void close() override;

 private:
  // The bar and the first of `statuses` (longest first) that leaves room for one on the
  // terminal's line; the last one cut to the line when none does.
  void redraw_status(const std::vector<std::string>& statuses);
  // Replaces the live line with `line`, cut to the terminal's width.
  void redraw(const std::string& line);

  const eval::ExperimentSpec* spec_;
  bool live_;
  bool line_open_ = false;
  std::int64_t generations_total_;
  std::int64_t generations_done_;
  std::int64_t done_here_ = 0;
  std::chrono::steady_clock::time_point start_;
  // Of the last round (all runs advancing together): evaluations and control steps per
  // second, and the time left once its generations are done.
  double evaluations_per_second_ = 0.0;
  double steps_per_second_ = 0.0;
  double eta_seconds_ = 0.0;
  // Piped, a long round's progress is printed at most this often (the live line: always).
  static constexpr double kPipedProgressInterval_s = 30.0;
  double next_piped_progress_s_ = 0.0;
};

[[nodiscard]] std::string format_duration(double seconds);

// The progress bar text: `width` cells, filled in proportion to done / total.
[[nodiscard]] std::string progress_bar(std::int64_t done, std::int64_t total, int width);

}  // namespace esc::cli
