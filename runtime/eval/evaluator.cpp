#include "runtime/eval/evaluator.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "runtime/control/controller.hpp"
#include "runtime/eval/epoch_stepper.hpp"
#include "runtime/eval/observe.hpp"
#include "runtime/genome/tree/codec.hpp"
#include "runtime/tree_control/tree_driver.hpp"

namespace esc::eval {

Evaluator::Evaluator(const ExperimentSpec& spec)
    : spec_(&spec),
      world_(world_of(spec)),
      folded_(static_cast<std::size_t>(spec.robots), StepAggregates(spec)),
      end_frame_(spec.step_aggregate_slot() + folded_.front().widest(), 0.0) {
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
  commands_.resize(static_cast<std::size_t>(spec.robots));
  acting_.resize(static_cast<std::size_t>(spec.robots));
  epoch_starts_.resize(static_cast<std::size_t>(spec.robots));
}

Evaluation Evaluator::evaluate(const control::ControllerSpec& controller,
                               std::span<const double> genome, std::uint64_t seed,
                               TraceSink* trace) {
  if (controller.is_tree()) return evaluate(controller, genome::tree::decode(genome, *controller.primitives), seed, trace);
  if (spec_->robots == 1 && !controller.per_body()) {
    control::Controller ctl(controller, genome, &tree_control::make_actor);
    control::Controller* const one = &ctl;
    return run(controller, std::span<control::Controller* const>(&one, 1), seed, trace);
  }
  const auto roles = static_cast<std::size_t>(spec_->roles);
  if (controller.per_body() && genome.size() != controller.genome_size())
    throw std::invalid_argument(fmt::format("a genome of `{}` holds its {} networks' {} weights, got {} values",
                                            controller.name, controller.networks.size(), controller.genome_size(),
                                            genome.size()));
  if (roles > 1 && genome.size() != spec_->genome_length(controller))
    throw std::invalid_argument(fmt::format("a genome of `{}` here holds {} roles of {} weights, got {} values",
                                            controller.name, roles, controller.genome_size(), genome.size()));
  // Robot i's network and its weights: its body's network and that network's slice (a
  // controller per body), else the controller's, role r's the r-th slice (the whole genome for
  // the clonal team).
  const std::size_t role_size = genome.size() / roles;
  const auto network_of = [&](std::size_t i) -> std::pair<const control::ControllerSpec*, std::span<const double>> {
    if (!controller.per_body()) return {&controller, genome.subspan((i % roles) * role_size, role_size)};
    const std::size_t b = spec_->body_of(i);
    if (b >= controller.body_networks.size())
      throw std::invalid_argument(fmt::format("controller `{}` names no network for body {} of the group",
                                              controller.name, b + 1));
    const std::size_t k = controller.body_networks[b];
    const control::ControllerSpec& network = controller.networks.at(k);
    return {&network, genome.subspan(controller.network_offset(k), network.genome_size())};
  };
  std::vector<std::unique_ptr<control::Controller>> group;
  std::vector<control::Controller*> drivers;
  for (std::size_t i = 0; i < static_cast<std::size_t>(spec_->robots); ++i) {
    const auto [network, weights] = network_of(i);
    group.push_back(std::make_unique<control::Controller>(*network, weights, &tree_control::make_actor));
    drivers.push_back(group.back().get());
  }
  return run(controller, std::span<control::Controller* const>(drivers), seed, trace);
}

Evaluation Evaluator::evaluate(const control::ControllerSpec& controller, const genome::tree::Tree& tree,
                               std::uint64_t seed, TraceSink* trace) {
  if (spec_->robots == 1) {
    tree_control::TreeDriver ctl(controller, tree);
    tree_control::TreeDriver* const one = &ctl;
    return run(controller, std::span<tree_control::TreeDriver* const>(&one, 1), seed, trace);
  }
  std::vector<std::unique_ptr<tree_control::TreeDriver>> group;
  std::vector<tree_control::TreeDriver*> drivers;
  for (int i = 0; i < spec_->robots; ++i) {
    group.push_back(std::make_unique<tree_control::TreeDriver>(controller, tree));
    drivers.push_back(group.back().get());
  }
  return run(controller, std::span<tree_control::TreeDriver* const>(drivers), seed, trace);
}

double Evaluator::end_term(const expr::Program& term, const std::vector<expr::StepAggregate>& folded,
                           const StepAggregates& values, const control::ControllerSpec& controller,
                           const expr::Frame& frame, std::int64_t steps, std::span<const std::int64_t> usage,
                           std::span<const std::int64_t> before) {
  std::copy(frame.begin(), frame.end(), end_frame_.begin());
  std::fill(end_frame_.begin() + expr::aggregate::steps, end_frame_.end(), 0.0);
  end_frame_[expr::aggregate::steps] = static_cast<double>(steps);
  for (std::size_t i = 0; i < usage.size(); ++i) {
    const int id = controller.choice_id(static_cast<int>(i));
    if (id < 0 || expr::aggregate::count + static_cast<std::size_t>(id) >= end_frame_.size()) continue;
    end_frame_[expr::aggregate::count + static_cast<std::size_t>(id)] +=
        static_cast<double>(usage[i] - (i < before.size() ? before[i] : 0));
  }
  if (!folded.empty()) values.write(folded, std::span<double>(end_frame_).subspan(spec_->step_aggregate_slot()));
  return term.eval(end_frame_);
}

// A group's usage as a robot's: each choice's steps over the robots divided by their number,
// the remainders given out largest first (the first choice on a tie) so that the counts still
// add up to the group's steps, as `steps` counts the group's control steps.
template <class Driver>
void Evaluator::share_usage(std::span<Driver* const> drivers, std::vector<std::int64_t>& usage) {
  const auto n = static_cast<std::int64_t>(drivers.size());
  std::vector<std::int64_t> remainder(usage.size(), 0);
  std::int64_t left = 0;
  for (std::size_t k = 0; k < usage.size(); ++k) {
    std::int64_t sum = 0;
    for (Driver* d : drivers) sum += d->usage()[k];
    usage[k] = sum / n;
    remainder[k] = sum % n;
    left += remainder[k];
  }
  for (left /= n; left > 0; --left) {
    const auto most = static_cast<std::size_t>(std::max_element(remainder.begin(), remainder.end()) - remainder.begin());
    ++usage[most];
    remainder[most] = -1;
  }
}

template <class Driver>
double Evaluator::end_over_robots(const expr::Program& term, const std::vector<expr::StepAggregate>& folded,
                                  const control::ControllerSpec& controller, const EpochStepper& epoch,
                                  std::span<Driver* const> drivers, std::int64_t steps, bool over_epoch,
                                  Reduction over) {
  const auto value = [&](std::size_t i) {
    const std::span<const std::int64_t> before =
        over_epoch ? std::span<const std::int64_t>(epoch_starts_[i]) : std::span<const std::int64_t>{};
    return end_term(term, folded, folded_[i], controller, epoch.frame(i), steps, drivers[i]->usage(), before);
  };
  if (drivers.size() == 1) return value(0);
  return reduce_over_robots(drivers.size(), over, value);
}

template <class Driver>
void Evaluator::reduce_descriptors(const control::ControllerSpec& controller, const EpochStepper& epoch,
                                   std::span<Driver* const> drivers, std::int64_t steps, int e,
                                   std::vector<double>& values) {
  for (std::size_t i = 0; i < spec_->descriptors.size(); ++i) {
    const DescriptorSpec& d = spec_->descriptors[i];
    if (d.at_evaluation) continue;
    const double v = end_over_robots(d.program, d.aggregates, controller, epoch, drivers, steps, true, d.over_robots);
    double& r = values[i];
    switch (d.reduce) {
      case Reduction::Mean:
      case Reduction::Sum: r += v; break;
      case Reduction::Min: r = e == 0 ? v : std::min(r, v); break;
      case Reduction::Max: r = e == 0 ? v : std::max(r, v); break;
      case Reduction::First: if (e == 0) r = v; break;
      case Reduction::Last: r = v; break;
    }
  }
}

template <class Driver>
Evaluation Evaluator::run(const control::ControllerSpec& controller, std::span<Driver* const> drivers,
                          std::uint64_t seed, TraceSink* trace) {
  const ExperimentSpec& s = *spec_;
  // A group's replay records every group observable, the pairs' ones too: they are only
  // written, so the evaluation is the same.
  StepperReads reads = stepper_reads(s, controller);
  if (trace != nullptr && drivers.size() > 1) reads.pairs = true;
  EpochStepper epoch(s, world_, reads);
  Evaluation result;
  result.objectives.assign(s.further.size(), 0.0);
  result.descriptors.assign(s.descriptors.size(), 0.0);
  // A trace's running fitness counts every term where it applies: an epoch's last step is
  // told after the epoch's end terms, the evaluation's after its own, so that the last step
  // holds the evaluation's fitness.
  for (StepAggregates& f : folded_) f.begin_evaluation();
  std::vector<TraceStep> last_step;   // the last step's, a TraceStep per robot
  const auto tell_last_step = [&] {
    for (TraceStep& t : last_step) {
      t.fitness = result.fitness;
      trace->on_step(t);
    }
    last_step.clear();
  };
  for (int e = 0; e < s.epochs; ++e) {
    epoch.begin(seed, e);
    for (StepAggregates& f : folded_) f.begin_epoch();
    for (std::size_t i = 0; i < drivers.size(); ++i) {
      drivers[i]->reset();
      epoch_starts_[i].assign(drivers[i]->usage().begin(), drivers[i]->usage().end());   // no allocation once grown
    }
    const std::int64_t steps_before = result.steps;
    while (epoch.steps_taken() < s.steps) {
      epoch.observe();
      for (std::size_t i = 0; i < drivers.size(); ++i) {
        commands_[i] = drivers[i]->step(epoch.frame(i));
        acting_[i] = controller.choice_id(drivers[i]->last_action());
      }
      const StepOutcome outcome = epoch.act(commands_, acting_);
      ++result.steps;
      if (!folded_.front().empty())
        for (std::size_t i = 0; i < folded_.size(); ++i)
          folded_[i].step(epoch.frame(i), epoch.steps_taken() - 1, result.steps - 1);
      result.fitness = add_fitness(result.fitness, outcome.term);
      for (std::size_t k = 0; k < s.further.size(); ++k)
        result.objectives[k] =
            add_fitness(result.objectives[k], epoch.over_robots(s.further[k].step, s.further[k].over_robots));
      if (trace != nullptr) [[unlikely]] {
        for (const TraceStep& t : last_step) trace->on_step(t);
        last_step.clear();
        for (std::size_t i = 0; i < drivers.size(); ++i)
          last_step.push_back(epoch.traced(commands_[i], drivers[i]->last_action(), result.fitness, i));
      }
      if (outcome.stop) break;
    }
    const std::int64_t epoch_steps = result.steps - steps_before;
    if (s.fitness.epoch_end)
      result.fitness += end_over_robots(*s.fitness.epoch_end, s.fitness.epoch_aggregates, controller, epoch, drivers,
                                        epoch_steps, true, s.fitness.over_robots);
    for (std::size_t k = 0; k < s.further.size(); ++k)
      if (s.further[k].epoch_end)
        result.objectives[k] += end_over_robots(*s.further[k].epoch_end, s.further[k].epoch_aggregates, controller,
                                                epoch, drivers, epoch_steps, true, s.further[k].over_robots);
    if (!s.descriptors.empty()) reduce_descriptors(controller, epoch, drivers, epoch_steps, e, result.descriptors);
    if (e + 1 < s.epochs) tell_last_step();
  }
  if (s.fitness.evaluation_end)
    result.fitness += end_over_robots(*s.fitness.evaluation_end, s.fitness.evaluation_aggregates, controller, epoch,
                                      drivers, result.steps, false, s.fitness.over_robots);
  tell_last_step();
  for (std::size_t k = 0; k < s.further.size(); ++k)
    if (s.further[k].evaluation_end)
      result.objectives[k] += end_over_robots(*s.further[k].evaluation_end, s.further[k].evaluation_aggregates,
                                              controller, epoch, drivers, result.steps, false, s.further[k].over_robots);
  for (std::size_t i = 0; i < s.descriptors.size(); ++i) {
    const DescriptorSpec& d = s.descriptors[i];
    if (d.at_evaluation)
      result.descriptors[i] =
          end_over_robots(d.program, d.aggregates, controller, epoch, drivers, result.steps, false, d.over_robots);
    else if (d.reduce == Reduction::Mean && s.epochs > 0) result.descriptors[i] /= s.epochs;
  }
  result.usage.assign(drivers[0]->usage().begin(), drivers[0]->usage().end());
  if (drivers.size() > 1) share_usage(drivers, result.usage);
  return result;
}

std::size_t replay_rows(const ExperimentSpec& spec) noexcept {
  const double rows = static_cast<double>(spec.epochs) * spec.steps * spec.robots;
  if (spec.robots == 1) return static_cast<std::size_t>(rows);
  return rows < static_cast<double>(kMaxReplayRows) ? static_cast<std::size_t>(rows) : kMaxReplayRows;
}

std::size_t trace_rows_kept(std::span<const TraceStep> trace, std::size_t limit) noexcept {
  if (trace.size() <= limit) return trace.size();
  std::size_t cut = limit;
  while (cut > 0 && trace[cut - 1].epoch == trace[limit].epoch) --cut;
  if (cut > 0) return cut;
  // Within the first epoch: back to the first robot of the step the limit falls in.
  for (cut = limit; cut > 0 && trace[cut].robot != 0; --cut) {}
  return cut;
}

}  // namespace esc::eval
