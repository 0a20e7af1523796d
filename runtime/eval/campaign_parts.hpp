#pragma once
// What the two generation loops of a campaign share (campaign.cpp: the ES for networks,
// tree_campaign.cpp: GP for trees): where evaluations run, the parallel evaluation of one
// generation, its statistics, the run's best so far and the replay of the best evaluation.
// Internal to esc_eval.
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
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

// evaluate(evaluator, i, seed): individual i of the generation, with its evaluation seed.
using EvaluateOne = std::function<Evaluation(Evaluator&, std::size_t, std::uint64_t)>;

// Evaluates individuals [0, n) of generation `generation` in parallel into fitness[0, n);
// returns the control steps simulated. Each result lands in its own slot, so the outcome
// does not depend on which worker or rank ran what.
std::int64_t evaluate_all(std::size_t n, std::uint64_t run_seed, int generation, Evaluators& ev,
                          const EvaluateOne& evaluate, std::vector<double>& fitness);

[[nodiscard]] GenerationStats summarise(int generation, std::span<const double> fitness, std::int64_t steps,
                                        double seconds);

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

// One run of a tree controller by genetic programming (tree_campaign.cpp).
[[nodiscard]] RunResult evolve_tree(const ExperimentSpec& spec, const control::ControllerSpec& controller, int run,
                                    const RunState* from, const CampaignOptions& options, Evaluators& ev,
                                    CampaignListener& listener);

}  // namespace esc::eval::detail
