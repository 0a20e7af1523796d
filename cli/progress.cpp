#include "cli/progress.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <fmt/format.h>

namespace esc::cli {

std::string format_duration(double seconds) {
  const auto s = static_cast<long long>(std::llround(std::max(0.0, seconds)));
  if (s >= 3600) return fmt::format("{}h{:02}m", s / 3600, (s % 3600) / 60);
  if (s >= 60) return fmt::format("{}m{:02}s", s / 60, s % 60);
  return fmt::format("{}s", s);
}

std::string progress_bar(std::int64_t done, std::int64_t total, int width) {
  const double f = total > 0 ? std::clamp(static_cast<double>(done) / static_cast<double>(total), 0.0, 1.0) : 1.0;
  const auto full = static_cast<int>(std::floor(f * width));
  std::string bar;
  for (int i = 0; i < width; ++i) bar += i < full ? "█" : "░";
  return bar;
}

ProgressPrinter::ProgressPrinter(const eval::ExperimentSpec& spec, eval::CampaignListener& next, bool live,
                                 std::int64_t already_done)
    : spec_(&spec),
      next_(&next),
      live_(live),
      generations_total_(spec.total_generations()),
      generations_done_(already_done),
      start_(std::chrono::steady_clock::now()) {}

void ProgressPrinter::round_evaluated(const eval::RoundStats& round) {
  next_->round_evaluated(round);
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const auto done_here = done_here_ + static_cast<std::int64_t>(round.runs);
  const auto left = generations_total_ - generations_done_ - static_cast<std::int64_t>(round.runs);
  eta_seconds_ = elapsed / static_cast<double>(done_here) * static_cast<double>(std::max<std::int64_t>(left, 0));
  evaluations_per_second_ = round.seconds > 0.0 ? static_cast<double>(round.evaluations) / round.seconds : 0.0;
  steps_per_second_ = round.seconds > 0.0 ? static_cast<double>(round.steps) / round.seconds : 0.0;
}

void ProgressPrinter::generation_done(const control::ControllerSpec& controller, int run,
                                      const eval::GenerationStats& g) {
  next_->generation_done(controller, run, g);
  ++generations_done_;
  ++done_here_;
  if (live_) {
    const double percent = 100.0 * static_cast<double>(generations_done_) / static_cast<double>(generations_total_);
    fmt::print("\r\033[K{} {:>3.0f}%  {} run {}/{} gen {}/{}  best {:.2f}  mean {:.2f}  {:.0f} eval/s  ETA {}",
               progress_bar(generations_done_, generations_total_, 24), percent, controller.name, run + 1,
               spec_->runs, g.generation + 1, spec_->generations_for(controller), g.best, g.mean,
               evaluations_per_second_, format_duration(eta_seconds_));
    line_open_ = true;
  } else {
    fmt::print("{:<8} run {:>2}/{:<2} gen {:>4}/{:<4} best {:>9.2f}  mean {:>9.2f}  {:>6.0f} eval/s  "
               "{:>5.0f}k steps/s  ETA {}\n",
               controller.name, run + 1, spec_->runs, g.generation + 1, spec_->generations_for(controller), g.best,
               g.mean, evaluations_per_second_, steps_per_second_ / 1000.0, format_duration(eta_seconds_));
  }
  std::fflush(stdout);
}

void ProgressPrinter::checkpoint(const control::ControllerSpec& controller, const eval::RunState& state) {
  next_->checkpoint(controller, state);
}

void ProgressPrinter::best_traced(const control::ControllerSpec& controller, const eval::RunResult& run,
                                  std::span<const eval::TraceStep> trace) {
  next_->best_traced(controller, run, trace);
}

void ProgressPrinter::run_done(const control::ControllerSpec& controller, const eval::RunResult& run) {
  next_->run_done(controller, run);
  if (live_) {
    fmt::print("\r\033[K{:<8} run {:>2}/{:<2} done: best fitness {:.2f}\n", controller.name, run.run + 1,
               spec_->runs, run.best_fitness);
    line_open_ = false;
    std::fflush(stdout);
  }
}

void ProgressPrinter::close() {
  if (line_open_) {
    fmt::print("\n");
    line_open_ = false;
    std::fflush(stdout);
  }
}

}  // namespace esc::cli
