#include "runtime/tree_control/tree_driver.hpp"

#include <stdexcept>
#include <variant>

#include "runtime/evo/gp/primitive_set.hpp"

namespace esc::tree_control {

namespace {

using control::BehaviorCall;
using control::Controller;
using control::ControllerSpec;
using control::FixedController;
using control::Head;
using control::SupervisedBehavior;

using evo::gp::Type;

Type root_of(Head h) noexcept {
  switch (h) {
    case Head::Classical: return Type::Wheels;
    case Head::Symbolic: return Type::Action;
    case Head::Supervisor: return Type::Behavior;
  }
  return Type::Wheels;
}

const ControllerSpec& checked(const ControllerSpec& spec) {
  if (!spec.is_tree()) throw std::invalid_argument("controller '" + spec.name + "' is not a tree controller");
  if (spec.primitives->root() != root_of(spec.head))
    throw std::invalid_argument("tree controller '" + spec.name + "': its primitives build " +
                                std::string(evo::gp::name_of(spec.primitives->root())) + " trees, its head needs " +
                                std::string(evo::gp::name_of(root_of(spec.head))));
  return spec;
}

std::vector<Controller> sub_controllers(const ControllerSpec& spec) {
  std::vector<Controller> subs;
  std::size_t n = 0;
  for (const SupervisedBehavior& b : spec.behaviors) n += std::holds_alternative<FixedController>(b.what) ? 1 : 0;
  subs.reserve(n);   // the delegates keep pointers to these
  for (const SupervisedBehavior& b : spec.behaviors) {
    const auto* fixed = std::get_if<FixedController>(&b.what);
    if (fixed == nullptr) continue;
    if (fixed->spec == nullptr)
      throw std::invalid_argument("tree controller '" + spec.name + "': behavior '" + b.name + "' has no controller");
    subs.emplace_back(*fixed->spec, fixed->genome);
  }
  return subs;
}

TreeControllerSpec tree_controller_spec(const ControllerSpec& spec, std::vector<Controller>& subs) {
  TreeControllerSpec t{spec.name, *spec.primitives, spec.actions, {}};
  std::size_t next_sub = 0;
  for (const SupervisedBehavior& b : spec.behaviors) {
    Delegate d;
    d.name = b.name;
    if (const auto* call = std::get_if<BehaviorCall>(&b.what)) {
      d.behavior = call->behavior;
      for (std::size_t k = 0; k < call->args.size() && k < d.params.size(); ++k) d.params[k] = call->args[k];
    } else {
      Controller* sub = &subs[next_sub++];
      d.step = [sub](expr::Frame& frame) { return sub->step(frame); };
      d.reset = [sub] { sub->reset(); };
    }
    t.behaviors.push_back(std::move(d));
  }
  return t;
}

}  // namespace

TreeDriver::TreeDriver(const control::ControllerSpec& spec, const evo::gp::Tree& tree)
    : subs_(sub_controllers(checked(spec))), tree_spec_(tree_controller_spec(spec, subs_)), ctl_(tree_spec_, tree) {}

}  // namespace esc::tree_control
