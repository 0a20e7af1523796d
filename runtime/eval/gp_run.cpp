// A run of a tree controller by generational genetic programming, with the guarantees of
// the ES run: every random stream comes from (run seed, purpose, generation, individual),
// so a run is the same for any thread count, any sharing among MPI ranks, and when resumed
// after any generation. Generation 0 evaluates the initial population (Stream::Init);
// generation g > 0 breeds from generation g - 1 with Rng(seed, Breed, g) and evaluates the
// result. Every individual is evaluated, elites too: fitness is measured from random start
// poses, so an elite is judged on this generation's streams like everyone else.
// A run that starts from a stored tree (`start from`) breeds generation 0 from copies of it
// with Rng(seed, Init), as the ES seeds its parents with copies, and keeps the tree itself
// unchanged as individual 0; one that only evaluates it (`evaluate from`) has that one tree.
#include <memory>
#include <optional>
#include <stdexcept>
#include <variant>

#include "runtime/core/rng.hpp"
#include "runtime/eval/campaign_parts.hpp"
#include "runtime/evo/gp/codec.hpp"
#include "runtime/evo/gp/print.hpp"
#include "runtime/tree_control/inline_actions.hpp"

namespace esc::eval::detail {

namespace {

// The tree as the body of a behavior that computes the same wheel commands, or "" when
// there is none (a Behavior tree; actions reading an arena's zones or lights).
std::string behavior_body(const control::ControllerSpec& controller, const evo::gp::Tree& tree) {
  const evo::gp::PrimitiveSet& set = *controller.primitives;
  if (set.root() == evo::gp::Type::Wheels) return evo::gp::to_script(tree, set);
  if (set.root() != evo::gp::Type::Action) return {};
  try {
    const tree_control::InlinedTree inlined = tree_control::inline_actions(tree, set, controller.actions);
    return evo::gp::to_script(inlined.tree, inlined.set);
  } catch (const std::invalid_argument&) {
    return {};
  }
}

class GpRun final : public RunJob {
 public:
  GpRun(const ExperimentSpec& spec, const control::ControllerSpec& controller, int run, const RunState* from)
      : RunJob(spec, controller, from != nullptr ? *from : fresh_state(spec, run, start_of(spec, controller, run))),
        start_(start_of(spec, controller, run)),
        evaluate_only_(start_ != nullptr && spec.evaluates_only()) {
    if (!evaluate_only_) gp_.emplace(*spec.gp, *controller.primitives);
    // A stored population must be one this script could have bred (the store keeps trees
    // without their primitive set).
    if (!state_.generations.empty() && population().size() != evaluations_per_generation())
      throw std::invalid_argument("tree controller '" + controller.name + "': the state to resume from holds " +
                                  std::to_string(population().size()) + " trees, the population is " +
                                  std::to_string(evaluations_per_generation()));
    for (const evo::gp::Individual& ind : population())
      if (const std::string why = evo::gp::check(ind.tree, *controller.primitives, controller.primitives->root());
          !why.empty())
        throw std::invalid_argument("tree controller '" + controller.name +
                                    "': a tree to resume from is not one of its primitive set: " + why);
  }

  std::size_t breed() override {
    const int g = generation();
    if (g > 0) {
      Rng rng(state_.seed, {static_cast<std::uint64_t>(Stream::Breed), static_cast<std::uint64_t>(g)});
      bred_ = gp_->breed(population(), rng);
      return bred_.size();
    }
    Rng init(state_.seed, {static_cast<std::uint64_t>(Stream::Init)});
    if (start_ == nullptr) {
      bred_ = gp_->initial(init);
      return bred_.size();
    }
    const evo::gp::Individual stored{evo::gp::decode(start_->genome, *controller_->primitives), 0.0};
    if (evaluate_only_) {
      bred_ = {stored};
      return bred_.size();
    }
    const std::vector<evo::gp::Individual> copies(static_cast<std::size_t>(gp_->settings().population), stored);
    bred_ = gp_->breed(copies, init);
    bred_.front() = stored;
    return bred_.size();
  }

  Evaluation evaluate(Evaluator& e, std::size_t i, std::uint64_t seed) const override {
    return e.evaluate(*controller_, bred_[i].tree, seed);
  }

  void evaluated(std::span<const double> fitness, const GenerationStats& stats) override {
    for (std::size_t i = 0; i < bred_.size(); ++i) bred_[i].fitness = fitness[i];
    if (const auto best = record(fitness, stats)) state_.best_genome = evo::gp::encode(bred_[*best].tree);
    population() = std::move(bred_);
    bred_.clear();
  }

  RunResult close(const ExperimentSpec& spec, const CampaignOptions& options, Evaluators& ev,
                  CampaignListener& listener) override {
    const bool has_best = state_.has_best;
    RunResult result = close_run(std::move(state_));
    if (!has_best) return result;
    const control::ControllerSpec& controller = *controller_;
    const evo::gp::Tree best = evo::gp::decode(result.best_genome, *controller.primitives);
    result.best_tree = evo::gp::to_script(best, *controller.primitives);
    result.best_behavior = behavior_body(controller, best);
    replay_best(spec, controller, result, options, ev, listener,
                [&](Evaluator& e, std::uint64_t seed, TraceSink* sink) {
                  return e.evaluate(controller, best, seed, sink);
                });
    return result;
  }

 private:
  static RunState fresh_state(const ExperimentSpec& spec, int run, const StartFrom::Origin* start) {
    RunState st = fresh_run(spec, run, start);
    st.algorithm = GpState{};
    return st;
  }

  [[nodiscard]] std::vector<evo::gp::Individual>& population() {
    return std::get<GpState>(state_.algorithm).population;
  }

  const StartFrom::Origin* start_;         // the stored tree the run starts from, or null
  bool evaluate_only_;
  std::optional<evo::gp::GeneticProgramming> gp_;   // none when the run only evaluates
  std::vector<evo::gp::Individual> bred_;
};

}  // namespace

std::unique_ptr<RunJob> gp_run(const ExperimentSpec& spec, const control::ControllerSpec& controller, int run,
                               const RunState* from) {
  if (!spec.gp && !spec.evaluates_only())
    throw std::invalid_argument("tree controller '" + controller.name + "' is compared, but experiment '" +
                                spec.name + "' has no GP settings");
  if (from != nullptr && !std::holds_alternative<GpState>(from->algorithm))
    throw std::invalid_argument("tree controller '" + controller.name +
                                "': the state to resume from is ES parents, not a GP population");
  return std::make_unique<GpRun>(spec, controller, run, from);
}

}  // namespace esc::eval::detail
