#pragma once
// Progress of a campaign on the terminal, one line per generation: controller, run,
// generation, best and mean fitness, evaluations per second and the estimated time left.
// Forwards every event to the next listener (the run directory).
#include <chrono>
#include <cstdint>

#include "runtime/eval/campaign.hpp"

namespace esc::cli {

class ProgressPrinter final : public eval::CampaignListener {
 public:
  ProgressPrinter(const eval::ExperimentSpec& spec, eval::CampaignListener& next);

  void generation_done(const control::ControllerSpec& controller, int run,
                       const eval::GenerationStats& stats) override;
  void run_done(const control::ControllerSpec& controller, const eval::RunResult& run) override;

 private:
  const eval::ExperimentSpec* spec_;
  eval::CampaignListener* next_;
  std::int64_t generations_total_;
  std::int64_t generations_done_ = 0;
  std::chrono::steady_clock::time_point start_;
};

[[nodiscard]] std::string format_duration(double seconds);

}  // namespace esc::cli
