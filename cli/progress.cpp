#include "cli/progress.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <unistd.h>

#include <fmt/format.h>

#include "cli/interrupt.hpp"
#include "cli/terminal.hpp"

namespace esc::cli {

std::string format_duration(double seconds) {
  const auto s = static_cast<long long>(std::llround(std::max(0.0, seconds)));
  if (s >= 3600) return fmt::format("{}h{:02}m", s / 3600, (s % 3600) / 60);
  if (s >= 60) return fmt::format("{}m{:02}s", s / 60, s % 60);
  return fmt::format("{}s", s);
}

namespace {

// The last column is left free: some terminals wrap as soon as it is written.
std::size_t usable_columns() {
  return static_cast<std::size_t>(std::max(1, terminal_columns(STDOUT_FILENO) - 1));
}

}  // namespace

void ProgressPrinter::redraw_status(const std::vector<std::string>& statuses) {
  constexpr std::size_t kWidest = 24;
  constexpr std::size_t kNarrowest = 5;   // below this a bar says nothing
  const std::size_t columns = usable_columns();
  for (const std::string& status : statuses) {
    const std::size_t width = display_width(status);
    if (width + kNarrowest > columns) continue;
    redraw(progress_bar(generations_done_, generations_total_, static_cast<int>(std::min(kWidest, columns - width))) +
           status);
    return;
  }
  redraw(statuses.back());
}

void ProgressPrinter::redraw(const std::string& line) {
  fmt::print("\r\033[K{}", fit_width(line, usable_columns()));
  line_open_ = true;
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
    : Progress(next),
      spec_(&spec),
      live_(live),
      generations_total_(spec.total_generations()),
      generations_done_(already_done),
      start_(std::chrono::steady_clock::now()) {}

void ProgressPrinter::round_progress(const eval::RoundProgress& p) {
  Progress::round_progress(p);
  const double percent = 100.0 * static_cast<double>(p.done) / static_cast<double>(std::max<std::int64_t>(p.evaluations, 1));
  const double rate = p.seconds > 0.0 ? static_cast<double>(p.done) / p.seconds : 0.0;
  const std::string status = fmt::format("this generation: {}/{} evaluations ({:.1f}%), {:.0f} eval/s", p.done,
                                         p.evaluations, percent, rate);
  if (live_) {
    redraw_status({" " + status});
  } else if (p.seconds >= next_piped_progress_s_) {
    next_piped_progress_s_ = p.seconds + kPipedProgressInterval_s;
    fmt::print("  {}\n", status);
  }
  std::fflush(stdout);
}

void ProgressPrinter::round_evaluated(const eval::RoundStats& round) {
  next_piped_progress_s_ = 0.0;
  Progress::round_evaluated(round);
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const auto done_here = done_here_ + static_cast<std::int64_t>(round.runs);
  const auto left = generations_total_ - generations_done_ - static_cast<std::int64_t>(round.runs);
  eta_seconds_ = elapsed / static_cast<double>(done_here) * static_cast<double>(std::max<std::int64_t>(left, 0));
  evaluations_per_second_ = round.seconds > 0.0 ? static_cast<double>(round.evaluations) / round.seconds : 0.0;
  steps_per_second_ = round.seconds > 0.0 ? static_cast<double>(round.steps) / round.seconds : 0.0;
}

void ProgressPrinter::generation_done(const control::ControllerSpec& controller, int run,
                                      const eval::GenerationStats& g) {
  Progress::generation_done(controller, run, g);
  ++generations_done_;
  ++done_here_;
  // Counted as the end message and `esc run --resume` count them ("3 of 16 generations"): the
  // generation stored as 0 (the initial population) is the first. Runs count from 1.
  const int generation = g.generation + 1;
  const int generations = spec_->generations_for(controller);
  if (live_) {
    const double percent = 100.0 * static_cast<double>(generations_done_) / static_cast<double>(generations_total_);
    const std::string where = fmt::format(" {:>3.0f}%  {} run {}/{} gen {}/{}  best {:.2f}", percent, controller.name,
                                          run + 1, spec_->runs, generation, generations, g.best);
    const std::string eta = fmt::format("ETA {}", format_duration(eta_seconds_));
    // What a narrow terminal leaves out first: the rate, then the mean.
    redraw_status({fmt::format("{}  mean {:.2f}  {:.0f} eval/s  {}", where, g.mean, evaluations_per_second_, eta),
                   fmt::format("{}  mean {:.2f}  {}", where, g.mean, eta), fmt::format("{}  {}", where, eta)});
  } else {
    fmt::print("{:<8} run {:>2}/{:<2} gen {:>4}/{:<4} best {:>9.2f}  mean {:>9.2f}  {:>6.0f} eval/s  "
               "{:>5.0f}k steps/s  ETA {}\n",
               controller.name, run + 1, spec_->runs, generation, generations, g.best, g.mean,
               evaluations_per_second_, steps_per_second_ / 1000.0, format_duration(eta_seconds_));
  }
  if (g.saturated > 0) {
    // Shown on its own line, live or piped: a fitness term overflows (docs/language.md).
    close();
    fmt::print("{:<8} run {:>2}/{:<2} gen {:>4}/{:<4}: {} of {} evaluations saturated at +-1e300\n", controller.name,
               run + 1, spec_->runs, generation, generations, g.saturated, g.evaluations);
  }
  std::fflush(stdout);
}

void ProgressPrinter::checkpoint(const control::ControllerSpec& controller, const eval::RunState& state) {
  StoringGeneration storing;   // a stop waits for the commit, and then counts it
  Progress::checkpoint(controller, state);
  storing.stored();
}

void ProgressPrinter::run_done(const control::ControllerSpec& controller, const eval::RunResult& run) {
  Progress::run_done(controller, run);
  if (live_) {
    redraw(fmt::format("{:<8} run {:>2}/{:<2} done: best fitness {:.2f}", controller.name, run.run + 1, spec_->runs,
                       run.best_fitness));
    fmt::print("\n");
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
