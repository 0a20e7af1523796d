#include "runtime/control/controller.hpp"

#include <stdexcept>
#include <string>
#include <utility>
#include <variant>

namespace esc::control {

Activation output_activation(Head h) noexcept {
  return h == Head::Classical ? Activation::Tanh : Activation::Sigmoid;
}

namespace {

std::string where(const ControllerSpec& spec) {
  return "controller '" + spec.name + "' (" + spec.architecture() + ")";
}

void check_program(const std::string& what, const expr::Program& p, const char* wheel) {
  const std::string w = what + " " + wheel + " wheel";
  if (!p.complete()) throw std::invalid_argument(w + " program is incomplete");
  for (const expr::Instr& in : p.code())
    if (in.op == expr::Op::Load && in.slot >= expr::kFrameSize)
      throw std::invalid_argument(w + " reads slot " + std::to_string(in.slot) +
                                  ", outside the frame");
}

// `what` names the behavior in messages, e.g. "controller 'sc' (8-14-6): action 'left'".
void check_behavior(const std::string& what, const Behavior& b) {
  if (b.params.size() > expr::kMaxParams)
    throw std::invalid_argument(what + " has " + std::to_string(b.params.size()) +
                                " parameters; at most " + std::to_string(expr::kMaxParams) +
                                " are supported");
  check_program(what, b.left, "left");
  check_program(what, b.right, "right");
}

std::string behavior_where(const ControllerSpec& spec, std::size_t i) {
  return where(spec) + ": behavior " + std::to_string(i) + " '" + spec.behaviors[i].name + "'";
}

// The factory of a controller given none: networks, each again with no factory.
std::unique_ptr<Actor> network(const ControllerSpec& spec, std::span<const double> genome, int depth) {
  if (spec.is_tree())
    throw std::invalid_argument(where(spec) + ": a frozen tree is built by tree_control::make_actor, which "
                                "this controller was not given");
  return std::make_unique<Controller>(spec, genome, nullptr, depth);
}

// Checks what Mlp and the sub-controllers do not, then returns the spec so it can run in
// the init list.
const ControllerSpec& checked(const ControllerSpec& spec, std::span<const double> genome,
                              int depth) {
  if (depth > Controller::kMaxNesting)
    throw std::invalid_argument(where(spec) + ": supervisors nested more than " +
                                std::to_string(Controller::kMaxNesting) +
                                " deep (does a supervisor contain itself?)");
  if (spec.is_tree())
    throw std::invalid_argument(where(spec) + ": a tree controller is run by tree_control::TreeDriver");
  if (spec.mlp.kind == NetworkKind::Elman && spec.mlp.hidden.size() != 1)
    throw std::invalid_argument(where(spec) + ": an Elman network needs exactly one hidden "
                                "layer, got " + std::to_string(spec.mlp.hidden.size()));
  if (spec.head != Head::Symbolic && !spec.actions.empty())
    throw std::invalid_argument(where(spec) + ": only a symbolic head has actions");
  if (spec.head != Head::Supervisor && !spec.behaviors.empty())
    throw std::invalid_argument(where(spec) + ": only a supervisor has behaviors");
  if (spec.head == Head::Symbolic) {
    if (spec.actions.empty())
      throw std::invalid_argument(where(spec) + ": a symbolic head needs at least one action");
    for (const Behavior& b : spec.actions)
      check_behavior(where(spec) + ": action '" + b.name + "'", b);
  }
  if (spec.head == Head::Supervisor) {
    if (spec.behaviors.empty())
      throw std::invalid_argument(where(spec) + ": a supervisor needs at least one behavior");
    for (std::size_t i = 0; i < spec.behaviors.size(); ++i) {
      const auto* call = std::get_if<BehaviorCall>(&spec.behaviors[i].what);
      if (call == nullptr) {
        if (std::get<FixedController>(spec.behaviors[i].what).spec == nullptr)
          throw std::invalid_argument(behavior_where(spec, i) + " has no controller spec");
        continue;  // the sub-controller checks itself when it is built
      }
      check_behavior(behavior_where(spec, i), call->behavior);
      if (call->args.size() != call->behavior.params.size())
        throw std::invalid_argument(behavior_where(spec, i) + " calls '" + call->behavior.name +
                                    "' with " + std::to_string(call->args.size()) +
                                    " arguments; it takes " +
                                    std::to_string(call->behavior.params.size()));
    }
  }
  if (!spec.is_graph() && genome.size() != spec.genome_size())
    throw std::invalid_argument(where(spec) + " needs a genome of " +
                                std::to_string(spec.genome_size()) + " weights, got " +
                                std::to_string(genome.size()));
  return spec;
}

std::variant<Mlp, GraphNet> network_of(const ControllerSpec& spec, std::span<const double> genome) {
  if (!spec.is_graph()) return Mlp(spec.mlp, spec.output_count(), output_activation(spec.head), genome);
  try {
    return GraphNet(spec.mlp, spec.output_count(), genome);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(where(spec) + ": " + e.what());
  }
}

}  // namespace

Controller::Controller(const ControllerSpec& spec, std::span<const double> genome)
    : Controller(spec, genome, nullptr, 0) {}

Controller::Controller(const ControllerSpec& spec, std::span<const double> genome, ActorFactory subs, int depth)
    : spec_(&checked(spec, genome, depth)),
      net_(network_of(spec, genome)) {
  if (spec.head == Head::Symbolic) {
    param_offset_.reserve(spec.actions.size());
    std::size_t next = spec.actions.size();
    for (const Behavior& b : spec.actions) {
      param_offset_.push_back(next);
      next += b.params.size();
    }
    usage_.assign(spec.actions.size(), 0);
  }
  if (spec.head == Head::Supervisor) {
    sub_index_.reserve(spec.behaviors.size());
    std::size_t n_subs = 0;
    for (const SupervisedBehavior& b : spec.behaviors)
      if (std::holds_alternative<FixedController>(b.what)) ++n_subs;
    subs_.reserve(n_subs);
    const ActorFactory make = subs != nullptr ? subs : &network;
    for (std::size_t i = 0; i < spec.behaviors.size(); ++i) {
      const auto* fixed = std::get_if<FixedController>(&spec.behaviors[i].what);
      if (fixed == nullptr) {
        sub_index_.push_back(-1);
        continue;
      }
      try {
        subs_.push_back(make(*fixed->spec, fixed->genome, depth + 1));
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(behavior_where(spec, i) + ": " + e.what());
      }
      sub_index_.push_back(static_cast<int>(subs_.size() - 1));
    }
    usage_.assign(spec.behaviors.size(), 0);
  }
}

void Controller::rebind(std::span<const double> genome) {
  if (auto* g = std::get_if<GraphNet>(&net_)) {
    try {
      g->rebind(genome);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(where(*spec_) + ": " + e.what());
    }
  } else {
    std::get<Mlp>(net_).rebind(genome);
  }
  reset();
  clear_usage();
}

void Controller::reset() noexcept {
  std::visit([](auto& net) { net.reset(); }, net_);
  for (const auto& s : subs_) s->reset();
  last_action_ = -1;
}

void Controller::clear_usage() noexcept {
  for (std::int64_t& u : usage_) u = 0;
  for (const auto& s : subs_) s->clear_usage();
}

const Actor* Controller::sub_controller(std::size_t i) const noexcept {
  if (i >= sub_index_.size() || sub_index_[i] < 0) return nullptr;
  return subs_[static_cast<std::size_t>(sub_index_[i])].get();
}

WheelCommand Controller::step(expr::Frame& frame) noexcept {
  if (auto* g = std::get_if<GraphNet>(&net_)) {
    g->forward(frame);
    return head([g](std::size_t i) { return g->output(i); }, frame);
  }
  Mlp& mlp = *std::get_if<Mlp>(&net_);
  mlp.forward(frame);
  return head([&mlp](std::size_t i) { return mlp.output(i); }, frame);
}

WheelCommand Controller::act(std::span<const double> outputs, expr::Frame& frame) noexcept {
  return head([outputs](std::size_t i) { return outputs[i]; }, frame);
}

template <class Outputs>
WheelCommand Controller::head(const Outputs& output, expr::Frame& frame) noexcept {
  if (spec_->head == Head::Classical) {
    last_action_ = -1;
    return {output(0), output(1)};
  }
  // Argmax over the activated outputs, not the sums: two sums that saturate the logistic
  // give equal outputs, and then the first wins.
  std::size_t best = 0;
  double best_out = output(0);
  const std::size_t n = usage_.size();  // actions or behaviors
  for (std::size_t i = 1; i < n; ++i)
    if (const double o = output(i); o > best_out) {  // strict: the first of equal outputs wins
      best = i;
      best_out = o;
    }
  last_action_ = static_cast<int>(best);
  ++usage_[best];

  if (spec_->head == Head::Symbolic) {
    // Only the chosen action's parameters are read, so only they are activated.
    const Behavior& action = spec_->actions[best];
    const std::size_t first = param_offset_[best];
    for (std::size_t k = 0; k < action.params.size(); ++k)
      frame[expr::slot::param + k] = output(first + k);
    return run_behavior(action, frame);
  }

  // Supervisor. Only the chosen behavior runs: the supervisor "decides at each time step
  // which one of the basic behaviors will be executed" (Godzik et al. 2003, "Supervisor architectures"), and
  // a behavior that is not executed does not compute. So an inactive sub-controller's
  // recurrent state stays frozen where it was last chosen (or zero since the epoch began),
  // as if the behavior had been switched off; this also makes a step cost one network
  // per level rather than all of them. The paper does not say which it did.
  if (const int s = sub_index_[best]; s >= 0) return subs_[static_cast<std::size_t>(s)]->step(frame);
  const auto& call = *std::get_if<BehaviorCall>(&spec_->behaviors[best].what);
  for (std::size_t k = 0; k < call.args.size(); ++k) frame[expr::slot::param + k] = call.args[k];
  return run_behavior(call.behavior, frame);
}

}  // namespace esc::control
