#include "runtime/tree_control/tree_driver.hpp"

#include <stdexcept>
#include <string>
#include <variant>

#include "runtime/control/controller.hpp"
#include "runtime/genome/tree/codec.hpp"
#include "runtime/genome/tree/primitive_set.hpp"

namespace esc::tree_control {

namespace {

using control::BehaviorCall;
using control::Controller;
using control::ControllerSpec;
using control::FixedController;
using control::Head;
using control::SupervisedBehavior;

using genome::tree::Type;

Type root_of(Head h) noexcept {
  switch (h) {
    case Head::Classical: return Type::Wheels;
    case Head::Symbolic: return Type::Action;
    case Head::Supervisor: return Type::Behavior;
  }
  return Type::Wheels;
}

const ControllerSpec& checked(const ControllerSpec& spec, int depth) {
  if (depth > Controller::kMaxNesting)
    throw std::invalid_argument("tree controller '" + spec.name + "': supervisors nested more than " +
                                std::to_string(Controller::kMaxNesting) + " deep (does a supervisor contain itself?)");
  if (!spec.is_tree()) throw std::invalid_argument("controller '" + spec.name + "' is not a tree controller");
  if (spec.primitives->root() != root_of(spec.head))
    throw std::invalid_argument("tree controller '" + spec.name + "': its primitives build " +
                                std::string(genome::tree::name_of(spec.primitives->root())) + " trees, its head needs " +
                                std::string(genome::tree::name_of(root_of(spec.head))));
  return spec;
}

std::vector<std::unique_ptr<control::Actor>> sub_controllers(const ControllerSpec& spec, int depth) {
  std::vector<std::unique_ptr<control::Actor>> subs;
  for (const SupervisedBehavior& b : spec.behaviors) {
    const auto* fixed = std::get_if<FixedController>(&b.what);
    if (fixed == nullptr) continue;
    if (fixed->spec == nullptr)
      throw std::invalid_argument("tree controller '" + spec.name + "': behavior '" + b.name + "' has no controller");
    try {
      subs.push_back(make_actor(*fixed->spec, fixed->genome, depth + 1));
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("tree controller '" + spec.name + "': behavior '" + b.name + "': " + e.what());
    }
  }
  return subs;
}

TreeControllerSpec tree_controller_spec(const ControllerSpec& spec,
                                        const std::vector<std::unique_ptr<control::Actor>>& subs) {
  TreeControllerSpec t{spec.name, *spec.primitives, spec.actions, {}};
  std::size_t next_sub = 0;
  for (const SupervisedBehavior& b : spec.behaviors) {
    Delegate d;
    d.name = b.name;
    if (const auto* call = std::get_if<BehaviorCall>(&b.what)) {
      d.behavior = call->behavior;
      for (std::size_t k = 0; k < call->args.size() && k < d.params.size(); ++k) d.params[k] = call->args[k];
    } else {
      control::Actor* sub = subs[next_sub++].get();
      d.step = [sub](expr::Frame& frame) { return sub->step(frame); };
      d.reset = [sub] { sub->reset(); };
    }
    t.behaviors.push_back(std::move(d));
  }
  return t;
}

}  // namespace

TreeDriver::TreeDriver(const control::ControllerSpec& spec, const genome::tree::Tree& tree, int depth)
    : subs_(sub_controllers(checked(spec, depth), depth)),
      tree_spec_(tree_controller_spec(spec, subs_)),
      ctl_(tree_spec_, tree),
      usage_(spec.choice_names().size(), 0) {}

void TreeDriver::rebind(const genome::tree::Tree& tree) {
  ctl_.rebind(tree);
  clear_usage();
}

control::WheelCommand TreeDriver::step(expr::Frame& frame) noexcept {
  const control::WheelCommand command = ctl_.step(frame);
  if (const int a = ctl_.last_action(); a >= 0) ++usage_[static_cast<std::size_t>(a)];
  return command;
}

void TreeDriver::clear_usage() noexcept {
  for (std::int64_t& u : usage_) u = 0;
  for (const auto& s : subs_) s->clear_usage();
}

std::unique_ptr<control::Actor> make_actor(const control::ControllerSpec& spec, std::span<const double> genome,
                                           int depth) {
  if (!spec.is_tree()) return std::make_unique<Controller>(spec, genome, &make_actor, depth);
  return std::make_unique<TreeDriver>(spec, genome::tree::decode(genome, *spec.primitives), depth);
}

}  // namespace esc::tree_control
