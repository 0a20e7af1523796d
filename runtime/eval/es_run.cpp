// A run of a network controller by the evolution strategy. Generation g's offspring are
// bred with Rng(run seed, Breed, g) from the parents selected after generation g - 1 (the
// initial population, Rng(run seed, Init), for g = 0), so a run continued from any
// checkpoint is the run that was not interrupted.
#include <stdexcept>
#include <variant>

#include "runtime/core/rng.hpp"
#include "runtime/eval/campaign_parts.hpp"
#include "runtime/evo/es.hpp"

namespace esc::eval::detail {

namespace {

RunState fresh_state(const ExperimentSpec& spec, const evo::EvolutionStrategy& es, int run,
                     const StartFrom::Origin* start) {
  RunState st = fresh_run(spec, run, start);
  if (start != nullptr) {
    st.algorithm = EsState{es.seeded(start->genome)};
    return st;
  }
  Rng init(st.seed, {static_cast<std::uint64_t>(Stream::Init)});
  st.algorithm = EsState{es.initial(init)};
  return st;
}

class EsRun final : public RunJob {
 public:
  EsRun(const ExperimentSpec& spec, const control::ControllerSpec& controller, int run, const RunState* from)
      : EsRun(spec, controller, run, from, evo::EvolutionStrategy(spec.es, controller.genome_size()),
              start_of(spec, controller, run)) {}

  // A run that starts from a stored genome keeps it unchanged as offspring 0 of
  // generation 0, so that generation measures it in the new setting; a run that only
  // evaluates it has that one offspring.
  std::size_t breed() override {
    const int g = generation();
    if (evaluate_only()) {
      offspring_ = {parents().front()};
      return offspring_.size();
    }
    Rng rng(state_.seed, {static_cast<std::uint64_t>(Stream::Breed), static_cast<std::uint64_t>(g)});
    offspring_ = es_.breed(parents(), rng);
    if (start_ != nullptr && g == 0) offspring_.front() = parents().front();
    return offspring_.size();
  }

  Evaluation evaluate(Evaluator& e, std::size_t i, std::uint64_t seed) const override {
    return e.evaluate(*controller_, offspring_[i].genes, seed);
  }

  void evaluated(std::span<const double> fitness, const GenerationStats& stats) override {
    for (std::size_t i = 0; i < offspring_.size(); ++i) offspring_[i].fitness = fitness[i];
    if (const auto best = record(fitness, stats)) state_.best_genome = offspring_[*best].genes;
    if (!evaluate_only()) parents() = es_.select(parents(), offspring_);
  }

  RunResult close(const ExperimentSpec& spec, const CampaignOptions& options, Evaluators& ev,
                  CampaignListener& listener) override {
    const bool has_best = state_.has_best;
    RunResult result = close_run(std::move(state_));
    if (has_best)
      replay_best(spec, *controller_, result, options, ev, listener,
                  [&](Evaluator& e, std::uint64_t seed, TraceSink* sink) {
                    return e.evaluate(*controller_, result.best_genome, seed, sink);
                  });
    return result;
  }

 private:
  EsRun(const ExperimentSpec& spec, const control::ControllerSpec& controller, int run, const RunState* from,
        evo::EvolutionStrategy es, const StartFrom::Origin* start)
      : RunJob(spec, controller, from != nullptr ? *from : fresh_state(spec, es, run, start)),
        es_(std::move(es)),
        start_(start),
        evaluate_only_(start != nullptr && spec.evaluates_only()) {}

  [[nodiscard]] bool evaluate_only() const noexcept { return evaluate_only_; }
  [[nodiscard]] std::vector<evo::Individual>& parents() { return std::get<EsState>(state_.algorithm).parents; }

  evo::EvolutionStrategy es_;
  const StartFrom::Origin* start_;   // the stored genome the run starts from, or null
  bool evaluate_only_;
  std::vector<evo::Individual> offspring_;
};

}  // namespace

std::unique_ptr<RunJob> es_run(const ExperimentSpec& spec, const control::ControllerSpec& controller, int run,
                               const RunState* from) {
  if (from != nullptr && !std::holds_alternative<EsState>(from->algorithm))
    throw std::invalid_argument("network controller '" + controller.name +
                                "': the state to resume from is a GP population, not ES parents");
  return std::make_unique<EsRun>(spec, controller, run, from);
}

}  // namespace esc::eval::detail
