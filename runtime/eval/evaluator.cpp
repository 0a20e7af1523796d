#include "runtime/eval/evaluator.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>

#include "runtime/control/controller.hpp"
#include "runtime/eval/epoch_stepper.hpp"
#include "runtime/eval/observe.hpp"
#include "runtime/genome/tree/codec.hpp"
#include "runtime/tree_control/tree_driver.hpp"

namespace esc::eval {

Evaluator::Evaluator(const ExperimentSpec& spec)
    : spec_(&spec),
      world_(spec.arena, spec.robot),
      folded_(spec),
      end_frame_(spec.step_aggregate_slot() + folded_.widest(), 0.0) {
  const auto check = [&](const expr::Program& term, const std::vector<expr::StepAggregate>& folded,
                          const std::string& owner) {
    if (!term.complete()) throw std::invalid_argument(owner + ": an end term is incomplete");
    const std::size_t slots = spec.step_aggregate_slot() + folded.size();
    for (const expr::Instr& in : term.code())
      if (in.op == expr::Op::Load && in.slot >= slots)
        throw std::invalid_argument(owner + ": an end term reads slot " + std::to_string(in.slot) +
                                    ", beyond the frame, the experiment's " + std::to_string(spec.choice_ids) +
                                    " choice counts and its " + std::to_string(folded.size()) + " step aggregates");
    for (const expr::StepAggregate& a : folded) {
      if (!a.of.complete()) throw std::invalid_argument(owner + ": a step aggregate is incomplete");
      for (const expr::Instr& in : a.of.code())
        if (in.op == expr::Op::Load && in.slot >= expr::kFrameSize)
          throw std::invalid_argument(owner + ": a step aggregate reads slot " + std::to_string(in.slot) +
                                      ", beyond the frame");
    }
  };
  std::vector<const FitnessSpec*> objectives{&spec.fitness};
  for (const FitnessSpec& f : spec.further) objectives.push_back(&f);
  for (const FitnessSpec* f : objectives) {
    if (f->epoch_end) check(*f->epoch_end, f->epoch_aggregates, "fitness '" + f->name + "'");
    if (f->evaluation_end) check(*f->evaluation_end, f->evaluation_aggregates, "fitness '" + f->name + "'");
  }
  for (const DescriptorSpec& d : spec.descriptors) check(d.program, d.aggregates, "descriptor '" + d.name + "'");
}

Evaluation Evaluator::evaluate(const control::ControllerSpec& controller,
                               std::span<const double> genome, std::uint64_t seed,
                               TraceSink* trace) {
  if (controller.is_tree()) return evaluate(controller, genome::tree::decode(genome, *controller.primitives), seed, trace);
  control::Controller ctl(controller, genome, &tree_control::make_actor);
  return run(controller, ctl, reads_slot(*spec_, controller, expr::slot::noise), seed, trace);
}

Evaluation Evaluator::evaluate(const control::ControllerSpec& controller, const genome::tree::Tree& tree,
                               std::uint64_t seed, TraceSink* trace) {
  tree_control::TreeDriver ctl(controller, tree);
  return run(controller, ctl, reads_slot(*spec_, controller, expr::slot::noise), seed, trace);
}

double Evaluator::end_term(const expr::Program& term, const std::vector<expr::StepAggregate>& folded,
                           const control::ControllerSpec& controller, const expr::Frame& frame, std::int64_t steps,
                           std::span<const std::int64_t> usage, std::span<const std::int64_t> before) {
  std::copy(frame.begin(), frame.end(), end_frame_.begin());
  std::fill(end_frame_.begin() + expr::aggregate::steps, end_frame_.end(), 0.0);
  end_frame_[expr::aggregate::steps] = static_cast<double>(steps);
  for (std::size_t i = 0; i < usage.size(); ++i) {
    const int id = controller.choice_id(static_cast<int>(i));
    if (id < 0 || expr::aggregate::count + static_cast<std::size_t>(id) >= end_frame_.size()) continue;
    end_frame_[expr::aggregate::count + static_cast<std::size_t>(id)] +=
        static_cast<double>(usage[i] - (i < before.size() ? before[i] : 0));
  }
  if (!folded.empty()) folded_.write(folded, std::span<double>(end_frame_).subspan(spec_->step_aggregate_slot()));
  return term.eval(end_frame_);
}

void Evaluator::reduce_descriptors(const control::ControllerSpec& controller, const expr::Frame& frame,
                                   std::int64_t steps, std::span<const std::int64_t> usage,
                                   std::span<const std::int64_t> before, int epoch, std::vector<double>& values) {
  for (std::size_t i = 0; i < spec_->descriptors.size(); ++i) {
    const DescriptorSpec& d = spec_->descriptors[i];
    if (d.at_evaluation) continue;
    const double v = end_term(d.program, d.aggregates, controller, frame, steps, usage, before);
    double& r = values[i];
    switch (d.reduce) {
      case Reduction::Mean:
      case Reduction::Sum: r += v; break;
      case Reduction::Min: r = epoch == 0 ? v : std::min(r, v); break;
      case Reduction::Max: r = epoch == 0 ? v : std::max(r, v); break;
      case Reduction::First: if (epoch == 0) r = v; break;
      case Reduction::Last: r = v; break;
    }
  }
}

template <class Driver>
Evaluation Evaluator::run(const control::ControllerSpec& controller, Driver& ctl, bool noise, std::uint64_t seed,
                          TraceSink* trace) {
  const ExperimentSpec& s = *spec_;
  EpochStepper epoch(s, world_, noise);
  Evaluation result;
  result.objectives.assign(s.further.size(), 0.0);
  result.descriptors.assign(s.descriptors.size(), 0.0);
  // A trace's running fitness counts every term where it applies: an epoch's last step is
  // told after the epoch's end terms, the evaluation's after its own, so that the last step
  // holds the evaluation's fitness.
  folded_.begin_evaluation();
  std::optional<TraceStep> last_step;
  const auto tell_last_step = [&] {
    if (!last_step) return;
    last_step->fitness = result.fitness;
    trace->on_step(*last_step);
    last_step.reset();
  };
  for (int e = 0; e < s.epochs; ++e) {
    epoch.begin(seed, e);
    folded_.begin_epoch();
    ctl.reset();
    epoch_start_.assign(ctl.usage().begin(), ctl.usage().end());   // no allocation once it has grown
    const std::int64_t steps_before = result.steps;
    while (epoch.steps_taken() < s.steps) {
      epoch.observe();
      const control::WheelCommand cmd = ctl.step(epoch.frame());
      const StepOutcome outcome = epoch.act(cmd, controller.choice_id(ctl.last_action()));
      ++result.steps;
      if (!folded_.empty()) folded_.step(epoch.frame(), epoch.steps_taken() - 1, result.steps - 1);
      result.fitness = add_fitness(result.fitness, outcome.term);
      for (std::size_t k = 0; k < s.further.size(); ++k)
        result.objectives[k] = add_fitness(result.objectives[k], s.further[k].step.eval(epoch.frame()));
      if (trace != nullptr) [[unlikely]] {
        if (last_step) trace->on_step(*last_step);
        last_step = epoch.traced(cmd, ctl.last_action(), result.fitness);
      }
      if (outcome.stop) break;
    }
    const std::int64_t epoch_steps = result.steps - steps_before;
    if (s.fitness.epoch_end)
      result.fitness += end_term(*s.fitness.epoch_end, s.fitness.epoch_aggregates, controller, epoch.frame(),
                                 epoch_steps, ctl.usage(), epoch_start_);
    for (std::size_t k = 0; k < s.further.size(); ++k)
      if (s.further[k].epoch_end)
        result.objectives[k] +=
            end_term(*s.further[k].epoch_end, s.further[k].epoch_aggregates, controller, epoch.frame(), epoch_steps,
                     ctl.usage(), epoch_start_);
    if (!s.descriptors.empty())
      reduce_descriptors(controller, epoch.frame(), epoch_steps, ctl.usage(), epoch_start_, e, result.descriptors);
    if (e + 1 < s.epochs) tell_last_step();
  }
  if (s.fitness.evaluation_end)
    result.fitness += end_term(*s.fitness.evaluation_end, s.fitness.evaluation_aggregates, controller, epoch.frame(),
                               result.steps, ctl.usage(), {});
  tell_last_step();
  for (std::size_t k = 0; k < s.further.size(); ++k)
    if (s.further[k].evaluation_end)
      result.objectives[k] += end_term(*s.further[k].evaluation_end, s.further[k].evaluation_aggregates, controller,
                                       epoch.frame(), result.steps, ctl.usage(), {});
  for (std::size_t i = 0; i < s.descriptors.size(); ++i) {
    const DescriptorSpec& d = s.descriptors[i];
    if (d.at_evaluation)
      result.descriptors[i] = end_term(d.program, d.aggregates, controller, epoch.frame(), result.steps, ctl.usage(), {});
    else if (d.reduce == Reduction::Mean && s.epochs > 0) result.descriptors[i] /= s.epochs;
  }
  result.usage.assign(ctl.usage().begin(), ctl.usage().end());
  return result;
}

}  // namespace esc::eval
