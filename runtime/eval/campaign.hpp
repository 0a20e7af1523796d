#pragma once
// A campaign: for every compared controller, `runs` independent evolutions of
// `generations` generations. Each run's seed is derived from the master seed and the run
// index alone, so all controllers of an experiment meet the same start poses (common
// random numbers make the comparison sharper). Offspring are evaluated in parallel; each
// evaluation's stream is derived from (run seed, generation, individual), so results are
// bit-identical for any thread count.
#include <cstdint>
#include <string>
#include <vector>

#include "runtime/eval/experiment.hpp"

namespace esc::eval {

struct GenerationStats {
  int generation = 0;          // from 0
  double best = 0.0;           // best fitness among this generation's evaluated offspring
  double mean = 0.0;
  double sd = 0.0;
  std::int64_t evaluations = 0;
  std::int64_t steps = 0;      // control steps simulated in this generation
  double seconds = 0.0;        // wall time of the generation (not part of the result proper)
};

struct RunResult {
  int run = 0;                 // from 0
  std::uint64_t seed = 0;
  std::vector<GenerationStats> generations;
  double best_fitness = 0.0;   // best over all generations
  std::vector<double> best_genome;
};

struct ControllerResult {
  std::string name;
  std::string architecture;
  std::size_t genome_size = 0;
  std::vector<RunResult> runs;
};

struct CampaignResult {
  std::string experiment;
  std::uint64_t seed = 0;
  std::vector<ControllerResult> controllers;
};

// Told about progress as the campaign goes; called from the thread that called
// run_campaign, never concurrently.
class CampaignListener {
 public:
  virtual ~CampaignListener() = default;
  virtual void generation_done(const control::ControllerSpec& /*controller*/, int /*run*/,
                               const GenerationStats& /*stats*/) {}
  virtual void run_done(const control::ControllerSpec& /*controller*/, const RunResult& /*run*/) {}
};

struct CampaignOptions {
  int threads = 0;             // 0: all hardware threads
};

[[nodiscard]] std::uint64_t run_seed(std::uint64_t master_seed, int run) noexcept;

// Throws std::invalid_argument on impossible ES settings (from the strategy).
[[nodiscard]] CampaignResult run_campaign(const ExperimentSpec& spec, const CampaignOptions& options,
                                          CampaignListener& listener);

}  // namespace esc::eval
