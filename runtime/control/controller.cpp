#include "runtime/control/controller.hpp"

#include <stdexcept>
#include <string>

namespace esc::control {

namespace {

Activation output_activation(Head h) noexcept {
  return h == Head::Classical ? Activation::Tanh : Activation::Sigmoid;
}

std::string where(const ControllerSpec& spec) {
  return "controller '" + spec.name + "' (" + spec.architecture() + ")";
}

void check_program(const ControllerSpec& spec, const Behavior& b, const expr::Program& p,
                   const char* wheel) {
  const std::string what = where(spec) + ": action '" + b.name + "' " + wheel + " wheel";
  if (!p.complete()) throw std::invalid_argument(what + " program is incomplete");
  for (const expr::Instr& in : p.code())
    if (in.op == expr::Op::Load && in.slot >= expr::kFrameSize)
      throw std::invalid_argument(what + " reads slot " + std::to_string(in.slot) +
                                  ", outside the frame");
}

// Checks what Mlp does not, then returns the spec so it can run in the init list.
const ControllerSpec& checked(const ControllerSpec& spec, std::span<const double> genome) {
  if (spec.head == Head::Symbolic) {
    if (spec.actions.empty())
      throw std::invalid_argument(where(spec) + ": a symbolic head needs at least one action");
    for (const Behavior& b : spec.actions) {
      if (b.params.size() > expr::kMaxParams)
        throw std::invalid_argument(where(spec) + ": action '" + b.name + "' has " +
                                    std::to_string(b.params.size()) +
                                    " parameters; at most " +
                                    std::to_string(expr::kMaxParams) + " are supported");
      check_program(spec, b, b.left, "left");
      check_program(spec, b, b.right, "right");
    }
  }
  if (genome.size() != spec.genome_size())
    throw std::invalid_argument(where(spec) + " needs a genome of " +
                                std::to_string(spec.genome_size()) + " weights, got " +
                                std::to_string(genome.size()));
  return spec;
}

}  // namespace

Controller::Controller(const ControllerSpec& spec, std::span<const double> genome)
    : spec_(&checked(spec, genome)),
      net_(spec.mlp, spec.output_count(), output_activation(spec.head), genome) {
  if (spec.head == Head::Symbolic) {
    param_offset_.reserve(spec.actions.size());
    std::size_t next = spec.actions.size();
    for (const Behavior& b : spec.actions) {
      param_offset_.push_back(next);
      next += b.params.size();
    }
  }
}

void Controller::rebind(std::span<const double> genome) {
  net_.rebind(genome);
  reset();
}

void Controller::reset() noexcept {
  net_.reset();
  last_action_ = -1;
}

WheelCommand Controller::step(expr::Frame& frame) noexcept {
  const std::span<const double> out = net_.forward(frame);
  if (spec_->head == Head::Classical) {
    last_action_ = -1;
    return {out[0], out[1]};
  }
  std::size_t best = 0;
  const std::size_t n = spec_->actions.size();
  for (std::size_t i = 1; i < n; ++i)
    if (out[i] > out[best]) best = i;  // strict: the first of equal outputs wins
  const Behavior& action = spec_->actions[best];
  const std::size_t first = param_offset_[best];
  for (std::size_t k = 0; k < action.params.size(); ++k)
    frame[expr::slot::param + k] = out[first + k];
  last_action_ = static_cast<int>(best);
  return run_behavior(action, frame);
}

}  // namespace esc::control
