#pragma once
// A compared tree controller ready to drive: control::ControllerSpec (what the compiler
// produces for `tree(...)`) bound to one tree. It builds the TreeControllerSpec the
// TreeController runs: the spec's primitives, its actions (an Action tree) or its supervised
// behaviors as delegates (a Behavior tree). A supervised behavior that is another
// experiment's evolved controller runs in a Controller owned here, through the delegate's
// step/reset hooks, so every driver has its own sub-controllers and their recurrent state.
// Same surface as control::Controller: reset() per epoch, step() per control step without
// allocation, last_action(). Build one per evaluation or rebind() it.
#include <vector>

#include "runtime/control/controller.hpp"
#include "runtime/control/controller_spec.hpp"
#include "runtime/tree_control/tree_controller.hpp"

namespace esc::tree_control {

class TreeDriver {
 public:
  // Throws std::invalid_argument when `spec` is not a tree controller, its head does not
  // match its primitives' root type, a supervised evolved controller cannot be built, or
  // `tree` is not a well-typed tree of the root type. `spec` must outlive the driver.
  TreeDriver(const control::ControllerSpec& spec, const evo::gp::Tree& tree);
  // The delegates point into this object.
  TreeDriver(const TreeDriver&) = delete;
  TreeDriver& operator=(const TreeDriver&) = delete;

  // Compiles another tree (allocates) and resets.
  void rebind(const evo::gp::Tree& tree) { ctl_.rebind(tree); }
  void reset() noexcept { ctl_.reset(); }
  control::WheelCommand step(expr::Frame& frame) noexcept { return ctl_.step(frame); }
  [[nodiscard]] int last_action() const noexcept { return ctl_.last_action(); }

  [[nodiscard]] const TreeControllerSpec& tree_spec() const noexcept { return tree_spec_; }

 private:
  std::vector<control::Controller> subs_;   // one per evolved behavior, in order; never reallocated
  TreeControllerSpec tree_spec_;
  TreeController ctl_;
};

}  // namespace esc::tree_control
