#include "runtime/tree_control/tree_controller.hpp"

#include <stdexcept>

#include <fmt/format.h>

#include "runtime/genome/tree/semantics.hpp"

namespace esc::tree_control {

namespace {

using control::Behavior;
using control::WheelCommand;

using genome::tree::Kind;
using genome::tree::Type;

std::string where(const TreeControllerSpec& spec) {
  return fmt::format("tree controller '{}' ({} tree)", spec.name, genome::tree::name_of(spec.primitives.root()));
}

void check_behavior(const TreeControllerSpec& spec, const Behavior& b) {
  if (b.params.size() > expr::kMaxParams)
    throw std::invalid_argument(fmt::format("{}: behavior '{}' has {} parameters, at most {}",
                                            where(spec), b.name, b.params.size(), expr::kMaxParams));
  for (const expr::Program* p : {&b.left, &b.right}) {
    if (!p->complete())
      throw std::invalid_argument(where(spec) + ": behavior '" + b.name + "' program is incomplete");
    for (const expr::Instr& in : p->code())
      if (in.op == expr::Op::Load && in.slot >= expr::kFrameSize)
        throw std::invalid_argument(fmt::format("{}: behavior '{}' reads slot {}, outside the frame",
                                                where(spec), b.name, in.slot));
  }
}

const TreeControllerSpec& checked(const TreeControllerSpec& spec) {
  const Type root = spec.primitives.root();
  if (root != Type::Wheels && root != Type::Action && root != Type::Behavior)
    throw std::invalid_argument(where(spec) + ": the root type must be Wheels, Action or Behavior");
  for (const genome::tree::Primitive& p : spec.primitives.primitives()) {
    if (p.kind == Kind::Action) {
      if (p.index >= spec.actions.size())
        throw std::invalid_argument(fmt::format("{}: action `{}` has index {}, but there are {} actions",
                                                where(spec), p.name, p.index, spec.actions.size()));
      const Behavior& b = spec.actions[p.index];
      if (b.params.size() != p.arity)
        throw std::invalid_argument(fmt::format(
            "{}: action `{}` passes {} parameters, but behavior '{}' takes {}", where(spec), p.name,
            p.arity, b.name, b.params.size()));
    }
    if (p.kind == Kind::Behavior && p.index >= spec.behaviors.size())
      throw std::invalid_argument(fmt::format("{}: behavior `{}` has index {}, but there are {} behaviors",
                                              where(spec), p.name, p.index, spec.behaviors.size()));
  }
  for (const Behavior& b : spec.actions) check_behavior(spec, b);
  for (const Delegate& d : spec.behaviors)
    if (!d.step) check_behavior(spec, d.behavior);
  return spec;
}

genome::tree::FlatProgram compiled(const TreeControllerSpec& spec, const genome::tree::Tree& tree) {
  if (const std::string why = genome::tree::check(tree, spec.primitives, spec.primitives.root());
      !why.empty())
    throw std::invalid_argument(where(spec) + ": ill-typed tree: " + why);
  return genome::tree::compile(tree, spec.primitives);
}

}  // namespace

TreeController::TreeController(const TreeControllerSpec& spec, const genome::tree::Tree& tree)
    : spec_(&checked(spec)), program_(compiled(spec, tree)) {}

void TreeController::rebind(const genome::tree::Tree& tree) {
  program_ = compiled(*spec_, tree);
  reset();
}

void TreeController::reset() noexcept {
  last_action_ = -1;
  for (const Delegate& d : spec_->behaviors)
    if (d.reset) d.reset();
}

WheelCommand TreeController::step(expr::Frame& frame) noexcept {
  const genome::tree::Output out = program_.run(frame, stack_);
  switch (program_.type()) {
    case Type::Action: {
      const Behavior& b = spec_->actions[static_cast<std::size_t>(out.index)];
      for (std::size_t k = 0; k < out.param_count; ++k) frame[expr::slot::param + k] = out.params[k];
      last_action_ = out.index;
      return run_behavior(b, frame);
    }
    case Type::Behavior: {
      const Delegate& d = spec_->behaviors[static_cast<std::size_t>(out.index)];
      last_action_ = out.index;
      if (d.step) return d.step(frame);
      for (std::size_t k = 0; k < d.behavior.params.size(); ++k)
        frame[expr::slot::param + k] = d.params[k];
      return run_behavior(d.behavior, frame);
    }
    default:
      last_action_ = -1;
      return {genome::tree::sem::wheel(out.left), genome::tree::sem::wheel(out.right)};
  }
}

}  // namespace esc::tree_control
