// A run of one controller by its optimizer: the one loop every algorithm runs in. What it
// adds to ask/tell is what every run needs: the run's best and where it happened, the
// optimizer's state after each generation (what the store keeps to resume and carry on),
// the first evaluation that met the experiment's success test, a stored genome to start
// from or only evaluate, and the trees' texts at the end.
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include "runtime/eval/campaign_parts.hpp"
#include "runtime/eval/run_optimizer.hpp"
#include "runtime/eval/success.hpp"
#include "runtime/genome/tree/codec.hpp"
#include "runtime/genome/tree/print.hpp"
#include "runtime/tree_control/inline_actions.hpp"

namespace esc::eval::detail {

namespace {

// The tree as the body of a behavior that computes the same wheel commands, or "" when
// there is none (a Behavior tree; actions reading an arena's zones or lights).
std::string behavior_body(const control::ControllerSpec& controller, const genome::tree::Tree& tree) {
  const genome::tree::PrimitiveSet& set = *controller.primitives;
  if (set.root() == genome::tree::Type::Wheels) return genome::tree::to_script(tree, set);
  if (set.root() != genome::tree::Type::Action) return {};
  try {
    const tree_control::InlinedTree inlined = tree_control::inline_actions(tree, set, controller.actions);
    return genome::tree::to_script(inlined.tree, inlined.set);
  } catch (const std::invalid_argument&) {
    return {};
  }
}

}  // namespace

RunJob::RunJob(const ExperimentSpec& spec, const control::ControllerSpec& controller, int run, const RunState* from)
    : spec_(&spec),
      controller_(&controller),
      generations_(spec.generations_for(controller)),
      evaluations_(spec.evaluations_per_generation(controller)) {
  const StartFrom::Origin* start = start_of(spec, controller, run);
  state_ = from != nullptr ? *from : fresh_run(spec, run, start);
  evo::Problem problem = spec.problem_of(controller);
  problem.seed = state_.seed;
  problem.start = start != nullptr ? &start->genome : nullptr;
  RunOptimizer made = make_run_optimizer(spec, controller, problem);
  if (auto kept = made.optimizer->members(false)) state_.member_layout = member_layout(spec, std::move(*kept));
  // A run that only evaluates has no state to go on from (and one stored by an esc before
  // schema 6 is its ES's or GP's).
  if (from == nullptr || from->generations.empty() || spec.evaluates_only()) {
    state_.optimizer = std::move(made.empty_state);
    state_.optimizer.bytes = made.optimizer->save();
  } else {
    load_run_state(made, controller, from->optimizer);
  }
  optimizer_ = std::move(made.optimizer);
}

bool RunJob::finished() const { return generation() >= generations_ || !stopped().empty(); }

std::string RunJob::stopped() const {
  if (std::string stop = optimizer_->stopped(); !stop.empty()) return stop;
  return spec_->stop_at_success && state_.success_evaluation ? std::string(kStopAtSuccess) : std::string();
}

std::size_t RunJob::breed() {
  candidates_ = optimizer_->ask(generation());
  return candidates_.size();
}

Evaluation RunJob::evaluate(Evaluator& e, std::size_t i, std::uint64_t seed) const {
  return e.evaluate(*controller_, candidates_[i], seed);
}

void RunJob::evaluated(std::span<const evo::Outcome> outcomes, const GenerationStats& stats) {
  std::vector<double> fitness(outcomes.size());
  for (std::size_t i = 0; i < outcomes.size(); ++i) fitness[i] = outcomes[i].objectives.front();
  optimizer_->tell(outcomes);
  if (!state_.success_evaluation)
    if (const auto first = first_success(*spec_, outcomes))
      state_.success_evaluation = evaluations_of(state_.generations) + static_cast<std::int64_t>(*first) + 1;
  GenerationStats& g = state_.generations.emplace_back(stats);
  g.metrics = optimizer_->metrics();
  // Candidate 0 of generation 0 is the stored genome unchanged.
  if (state_.transfer && stats.generation == 0 && !fitness.empty()) state_.transfer->fitness_here = fitness.front();
  if (const auto best = improve_best(state_, stats.generation, fitness)) state_.best_genome = candidates_[*best];
  state_.optimizer.bytes = optimizer_->save();
  if (state_.member_layout) {
    state_.members = std::move(optimizer_->members(true)->members);
    const std::vector<bool>& minimized = state_.member_layout->minimized;
    for (evo::Member& m : state_.members)
      for (std::size_t i = 0; i < m.objectives.size() && i < minimized.size(); ++i)
        if (minimized[i]) m.objectives[i] = -m.objectives[i];
  }
  candidates_.clear();
}

RunResult RunJob::close(const ExperimentSpec& spec, const CampaignOptions& options, Evaluators& ev,
                        CampaignListener& listener) {
  const bool has_best = state_.has_best;
  std::string stop = stopped();
  RunResult result = close_run(std::move(state_));
  result.stopped = std::move(stop);
  if (!has_best) return result;
  const control::ControllerSpec& controller = *controller_;
  if (controller.is_tree()) {
    const genome::tree::Tree best = genome::tree::decode(result.best_genome, *controller.primitives);
    result.best_tree = genome::tree::to_script(best, *controller.primitives);
    result.best_behavior = behavior_body(controller, best);
  }
  replay_best(spec, controller, result, options, ev, listener,
              [&](Evaluator& e, std::uint64_t seed, TraceSink* sink) {
                return e.evaluate(controller, result.best_genome, seed, sink);
              });
  return result;
}

}  // namespace esc::eval::detail
