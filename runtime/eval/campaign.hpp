#pragma once
// A campaign: for every compared controller, `runs` independent evolutions of
// `generations` generations, each by the optimizer the experiment names for it (evo::Optimizer).
// Each run's seed is derived from the master seed and the run index alone, so all controllers of an experiment meet the same start poses (common
// random numbers make the comparison sharper). Offspring are evaluated in parallel; each
// evaluation's stream is derived from (run seed, generation, individual), so results are
// bit-identical for any thread count.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/eval/evaluator.hpp"
#include "runtime/eval/experiment.hpp"
#include "runtime/eval/run_state.hpp"
#include "runtime/evo/optimizer.hpp"

namespace esc::eval {

// One round of the campaign: a generation of every run advancing together, evaluated as
// one pool.
struct RoundStats {
  std::size_t runs = 0;
  std::int64_t evaluations = 0;
  std::int64_t steps = 0;
  double seconds = 0.0;        // wall time
};

// How far the evaluation of a long round has come (lambda 1,000,000 takes a while).
struct RoundProgress {
  std::int64_t done = 0;       // evaluations finished in this process (under MPI: on this rank)
  std::int64_t evaluations = 0;   // in the whole round, all ranks
  double seconds = 0.0;        // since the round began
};

// RunResult::stopped of a run the experiment's `stop at success` ended.
inline constexpr std::string_view kStopAtSuccess = "stop_at_success";

struct RunResult {
  int run = 0;                 // from 0
  std::uint64_t seed = 0;
  std::vector<GenerationStats> generations;
  double best_fitness = 0.0;   // best over all generations
  // Network weights; for a tree controller the best tree encoded (runtime/genome/tree/codec.hpp).
  std::vector<double> best_genome;
  int best_generation = 0;     // where the best evaluation happened: its generation and
  int best_index = 0;          // offspring index, which fix its evaluation stream
  // Control steps on which each action (symbolic head) or behavior (supervisor) acted,
  // over the best evaluation replayed, in ControllerSpec::choice_names() order; empty for
  // a classical head.
  std::vector<std::int64_t> action_usage;
  std::string best_tree{};     // tree controllers: the best tree as script code (genome::tree::to_script)
  // The best Wheels or Action tree as a behavior's body, `wheels(LEFT, RIGHT)`, computing the
  // same commands (an Action tree with its actions inlined); empty for a Behavior tree.
  std::string best_behavior{};
  std::optional<Transfer> transfer{};   // a run that started from a stored genome
  // Why the run ended before the last generation: its optimizer's stop (CMA-ES's
  // `stop_sigma`, ...) or kStopAtSuccess; empty when it went through every generation.
  std::string stopped{};
  std::optional<std::int64_t> success_evaluation{};   // as RunState's
};

// Seed of the evaluation of offspring `index` of generation `generation` of a run.
[[nodiscard]] std::uint64_t evaluation_seed(std::uint64_t run_seed, int generation, std::size_t index) noexcept;
// Seed of the evaluation that measured a front member or archive elite (`measured` known).
[[nodiscard]] inline std::uint64_t evaluation_seed_of(std::uint64_t run_seed, const evo::Measured& measured) noexcept {
  return evaluation_seed(run_seed, static_cast<int>(measured.generation), static_cast<std::size_t>(measured.candidate));
}

// What the store names the values and cells `kept` holds (each run's first generation makes
// it): the optimizer's own objectives, then the experiment's (the fitness first) with which
// are minimised, and its descriptors.
[[nodiscard]] std::shared_ptr<const MemberLayout> member_layout(const ExperimentSpec& spec, evo::Members kept);

struct ControllerResult {
  std::string name;
  std::string architecture;
  std::size_t genome_size = 0;
  std::vector<RunResult> runs;
  std::vector<std::string> choices;   // names of the actions or behaviors (RunResult::action_usage)
};

struct CampaignResult {
  std::string experiment;
  std::uint64_t seed = 0;
  int robots = 1;   // the group's robots (ExperimentSpec::robots)
  int roles = 1;    // and its roles (ExperimentSpec::roles)
  // A group of several bodies: its `bodies` setting ("khepera x 2, lit x 3"); empty otherwise.
  std::string bodies;
  // The experiment's success test as resolved (SuccessSpec::text); empty when it declares
  // none, and then no run's success is shown.
  std::string success{};
  std::vector<ControllerResult> controllers;
};

// `spec`'s result before any run: its name, seed, group and success test, no controllers.
// What a campaign's result and a run directory's first summary.json start from.
[[nodiscard]] CampaignResult campaign_result_of(const ExperimentSpec& spec);

inline constexpr double kRoundProgressInterval_s = 2.0;

// Told about progress as the campaign goes; called from the thread that called
// run_campaign (round_progress excepted), never concurrently. When several runs advance together, their events
// interleave: each run's own events come in order, and its run_done after its last
// generation.
class CampaignListener {
 public:
  virtual ~CampaignListener() = default;
  // While a round's pool is evaluated, every kRoundProgressInterval_s once the round has
  // taken that long: no effect on any result. The one event that comes from a worker
  // thread; never concurrently with itself or another event.
  virtual void round_progress(const RoundProgress& /*progress*/) {}
  // Once a round's pool is evaluated, before the generation_done of each of its runs.
  virtual void round_evaluated(const RoundStats& /*round*/) {}
  // Once a generation of a run is evaluated, before its generation_done: what each candidate
  // measured, in candidate order, as its optimizer is told (the fitness first, then the
  // further objectives, each maximised: a minimised one negated; then the descriptors).
  virtual void candidates_evaluated(const control::ControllerSpec& /*controller*/, int /*run*/, int /*generation*/,
                                    std::span<const evo::Outcome> /*outcomes*/) {}
  virtual void generation_done(const control::ControllerSpec& /*controller*/, int /*run*/,
                               const GenerationStats& /*stats*/) {}
  // After generation_done, with the whole state of the run: what a store commits to be
  // able to resume (see RunState).
  virtual void checkpoint(const control::ControllerSpec& /*controller*/, const RunState& /*state*/) {}
  // Before run_done: every step of the run's best evaluation, replayed (same seed, same
  // fitness). Only called when CampaignOptions::trace_best is set.
  virtual void best_traced(const control::ControllerSpec& /*controller*/, const RunResult& /*run*/,
                           std::span<const TraceStep> /*trace*/) {}
  virtual void run_done(const control::ControllerSpec& /*controller*/, const RunResult& /*run*/) {}
};

// Where to pick a campaign up again: the finished runs and the runs in progress, found
// by controller name and run index. Finished runs are taken as they are (the listener
// hears nothing of them); a run in progress continues from its state.
struct ResumePoint {
  struct Finished {
    std::string controller;
    RunResult result;
  };
  struct InProgress {
    std::string controller;
    RunState state;
  };
  std::vector<Finished> finished;
  std::vector<InProgress> in_progress;
};

struct CampaignOptions {
  int threads = 0;                        // 0: all hardware threads
  const ResumePoint* resume = nullptr;    // none: start from scratch
  bool trace_best = false;                // replay each run's best evaluation for best_traced
  // How many runs advance together, their generations' evaluations dealt out as one pool;
  // 0: as many as keep every worker of every rank busy (campaign.cpp). Results do not
  // depend on it; the order in which the listener hears of runs does.
  int runs_at_once = 0;
  // The runs to make (from 0), each as in the whole campaign (its seed depends on its index
  // alone); the others are left empty (RunResult{}) in the result. Empty: every run.
  std::vector<int> only_runs{};
};

[[nodiscard]] std::uint64_t run_seed(std::uint64_t master_seed, int run) noexcept;

// Whether another run joins the `active_runs` advancing together, whose generations pool
// `pooled_evaluations` evaluations, on `workers` workers (threads of all ranks), under
// CampaignOptions::runs_at_once. Shared with the campaign's wall-time estimate.
[[nodiscard]] bool room_for_another_run(std::size_t active_runs, std::size_t pooled_evaluations,
                                        std::size_t workers, int runs_at_once) noexcept;

// Throws std::invalid_argument on impossible ES or GP settings (from the algorithms), a
// tree controller compared without GP settings, or dependencies not prepared
// (ExperimentSpec::unprepared).
[[nodiscard]] CampaignResult run_campaign(const ExperimentSpec& spec, const CampaignOptions& options,
                                          CampaignListener& listener);

}  // namespace esc::eval
