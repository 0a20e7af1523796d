#include "cli/progress.hpp"

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

ProgressPrinter::ProgressPrinter(const eval::ExperimentSpec& spec, eval::CampaignListener& next)
    : spec_(&spec),
      next_(&next),
      generations_total_(static_cast<std::int64_t>(spec.controllers.size()) * spec.runs * spec.es.generations),
      start_(std::chrono::steady_clock::now()) {}

void ProgressPrinter::generation_done(const control::ControllerSpec& controller, int run,
                                      const eval::GenerationStats& g) {
  next_->generation_done(controller, run, g);
  ++generations_done_;
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double eta = elapsed / static_cast<double>(generations_done_) *
                     static_cast<double>(generations_total_ - generations_done_);
  const double rate = g.seconds > 0.0 ? static_cast<double>(g.evaluations) / g.seconds : 0.0;
  const double steps_rate = g.seconds > 0.0 ? static_cast<double>(g.steps) / g.seconds : 0.0;
  fmt::print("{:<8} run {:>2}/{:<2} gen {:>4}/{:<4} best {:>9.2f}  mean {:>9.2f}  {:>6.0f} eval/s  "
             "{:>5.0f}k steps/s  ETA {}\n",
             controller.name, run + 1, spec_->runs, g.generation + 1, spec_->es.generations, g.best, g.mean,
             rate, steps_rate / 1000.0, format_duration(eta));
  std::fflush(stdout);
}

void ProgressPrinter::run_done(const control::ControllerSpec& controller, const eval::RunResult& run) {
  next_->run_done(controller, run);
}

}  // namespace esc::cli
