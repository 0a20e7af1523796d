#pragma once
// The parts of a campaign (campaign.cpp) below the loop over runs: a run as a job that
// advances one generation at a time (run_job.cpp), whatever its optimizer, so that the
// campaign can advance several runs together and deal out their evaluations as one pool.
// Internal to esc_eval.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <tbb/enumerable_thread_specific.h>

#include "runtime/dist/distribution.hpp"
#include "runtime/eval/campaign.hpp"

namespace esc::eval::detail {

using Workers = tbb::enumerable_thread_specific<Evaluator>;

// Where evaluations run: this process's threads, and the other MPI ranks if any.
struct Evaluators {
  Workers& workers;
  dist::Distribution& distribution;
  std::size_t threads;   // this process's worker threads
};

// One run of one controller by its optimizer (evo::Optimizer, whichever algorithm the
// experiment names for it). The campaign calls breed(), evaluates the candidates it made
// (concurrently, in any order, on any rank), then evaluated(); until finished(). Every
// random stream comes from (run seed, purpose, generation, individual), so the run is the
// same however its evaluations were shared out and whichever runs it advanced with.
class RunJob {
 public:
  // A fresh run, or one continued from `from`. Throws std::invalid_argument on impossible
  // settings, a tree controller compared without GP settings, or a state `from` that the
  // controller's optimizer did not save or cannot read.
  RunJob(const ExperimentSpec& spec, const control::ControllerSpec& controller, int run, const RunState* from);
  RunJob(const RunJob&) = delete;
  RunJob& operator=(const RunJob&) = delete;

  [[nodiscard]] const ExperimentSpec& spec() const noexcept { return *spec_; }
  [[nodiscard]] const control::ControllerSpec& controller() const noexcept { return *controller_; }
  [[nodiscard]] const RunState& state() const noexcept { return state_; }
  // The generation breed() makes next.
  [[nodiscard]] int generation() const noexcept { return static_cast<int>(state_.generations.size()); }
  // After the last generation, or once the run has stopped early.
  [[nodiscard]] bool finished() const;
  // Why the run ended before its last generation (the optimizer's stop, or
  // `stop_at_success`), or "".
  [[nodiscard]] std::string stopped() const;
  // How many candidates each generation evaluates.
  [[nodiscard]] std::size_t evaluations_per_generation() const noexcept { return evaluations_; }

  // Makes generation generation()'s candidates; returns how many there are.
  std::size_t breed();
  // Evaluates candidate i of the bred generation; called concurrently for different i.
  [[nodiscard]] Evaluation evaluate(Evaluator& e, std::size_t i, std::uint64_t seed) const;
  // What the bred generation's candidates measured (in candidate order; objectives[0] the
  // fitness) and its statistics: tells the optimizer, keeps the run's best and the
  // optimizer's state.
  void evaluated(std::span<const evo::Outcome> outcomes, const GenerationStats& stats);
  // The finished run; its best evaluation replayed where the options or the controller
  // ask for it (replay_best).
  [[nodiscard]] RunResult close(const ExperimentSpec& spec, const CampaignOptions& options, Evaluators& ev,
                                CampaignListener& listener);

 private:
  const ExperimentSpec* spec_;
  const control::ControllerSpec* controller_;
  RunState state_;
  int generations_;
  std::size_t evaluations_;
  std::unique_ptr<evo::Optimizer> optimizer_;
  std::vector<evo::Genome> candidates_;
};

// Where run `run` of `controller` starts from (`start from` / `evaluate from`), or null when
// it starts from a random population.
[[nodiscard]] const StartFrom::Origin* start_of(const ExperimentSpec& spec, const control::ControllerSpec& controller,
                                                int run) noexcept;
// A run before its first generation: its index, seed, and where it starts from if it does.
[[nodiscard]] RunState fresh_run(const ExperimentSpec& spec, int run, const StartFrom::Origin* start);

[[nodiscard]] GenerationStats summarise(int generation, std::span<const double> fitness, std::int64_t steps,
                                        double seconds);

// What a round's pool holds per evaluation: its fitness, its steps, then the steps of each
// choice of its controller (Evaluation::usage), `width` doubles in all (exact: counts stay
// below 2^53), so that MPI ranks exchange them as doubles.
inline constexpr std::size_t kResultFitness = 0;
inline constexpr std::size_t kResultSteps = 1;
inline constexpr std::size_t kResultUsage = 2;
// After the usage columns (as many as the most choices of a controller in the round), the
// experiment's further objectives, then its descriptors.
struct ResultColumns {
  std::size_t objectives = 0;    // the first further objective's column
  std::size_t descriptors = 0;   // the first descriptor's column
  std::size_t width = 0;
};
[[nodiscard]] ResultColumns result_columns(const ExperimentSpec& spec, std::size_t most_choices) noexcept;
// Writes `e` into `row` (columns.width doubles).
void write_result(const Evaluation& e, const ResultColumns& columns, double* row) noexcept;
// Candidate i's outcome from `rows` (columns.width doubles each) as optimizers see it:
// every objective maximised (a minimised one negated), the descriptors as measured.
[[nodiscard]] std::vector<evo::Outcome> outcomes_of(const ExperimentSpec& spec, std::span<const double> rows,
                                                    const ResultColumns& columns);
// A generation's usage from its evaluations' rows (`width` doubles each, as above), for a
// controller of `choices` choices; empty when it has none.
[[nodiscard]] GenerationUsage summarise_usage(std::span<const double> rows, std::size_t width, std::size_t choices);

// Records the first individual of this generation that beats the run's best so far (its
// fitness, generation and index: the caller stores its genome). Returns its index.
std::optional<std::size_t> improve_best(RunState& st, int generation, std::span<const double> fitness);

// The run's result from its final state (best genome included).
[[nodiscard]] RunResult close_run(RunState&& st);

// Replays the run's best evaluation (same genome, same stream, so the same fitness) when
// there is behavior usage to count or options.trace_best asks for the trace.
// replay(evaluator, seed, sink) evaluates the best genome.
void replay_best(const ExperimentSpec& spec, const control::ControllerSpec& controller, RunResult& result,
                 const CampaignOptions& options, Evaluators& ev, CampaignListener& listener,
                 const std::function<Evaluation(Evaluator&, std::uint64_t, TraceSink*)>& replay);

}  // namespace esc::eval::detail
