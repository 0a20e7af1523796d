#pragma once
// A compared tree controller ready to drive: control::ControllerSpec (what the compiler
// produces for `tree(...)`) bound to one tree. It builds the TreeControllerSpec the
// TreeController runs: the spec's primitives, its actions (an Action tree) or its supervised
// behaviors as delegates (a Behavior tree). A supervised behavior that is another
// experiment's evolved controller (a network or a tree) runs in an actor owned here (built by
// make_actor), through the delegate's step/reset hooks, so every driver has its own
// sub-controllers and their recurrent state. An Actor like control::Controller: reset() per
// epoch, step() per control step without allocation, last_action(), usage(); so a tree can
// itself be a frozen behavior of a supervisor. Build one per evaluation or rebind() it.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "runtime/control/actor.hpp"
#include "runtime/control/controller_spec.hpp"
#include "runtime/tree_control/tree_controller.hpp"

namespace esc::tree_control {

class TreeDriver final : public control::Actor {
 public:
  // Throws std::invalid_argument when `spec` is not a tree controller, its head does not
  // match its primitives' root type, a supervised evolved controller cannot be built, or
  // `tree` is not a well-typed tree of the root type. `spec` must outlive the driver.
  // `depth`: levels of supervision above it (control::Controller::kMaxNesting at most).
  TreeDriver(const control::ControllerSpec& spec, const genome::tree::Tree& tree, int depth = 0);
  // The controller points into this object.
  TreeDriver(TreeDriver&&) = delete;
  TreeDriver& operator=(TreeDriver&&) = delete;

  // Compiles another tree (allocates), resets and clears the usage counts.
  void rebind(const genome::tree::Tree& tree);
  void reset() noexcept override { ctl_.reset(); }
  control::WheelCommand step(expr::Frame& frame) noexcept override;
  [[nodiscard]] int last_action() const noexcept override { return ctl_.last_action(); }
  // Steps spent in each action (Action tree) or behavior (Behavior tree), in spec order;
  // empty for a Wheels tree.
  [[nodiscard]] std::span<const std::int64_t> usage() const noexcept override { return usage_; }
  void clear_usage() noexcept override;

  [[nodiscard]] const TreeControllerSpec& tree_spec() const noexcept { return tree_spec_; }

 private:
  std::vector<std::unique_ptr<control::Actor>> subs_;   // one per evolved behavior, in order
  TreeControllerSpec tree_spec_;
  TreeController ctl_;
  std::vector<std::int64_t> usage_;
};

// The actor that runs a frozen controller: a TreeDriver for a tree (its genome the encoded
// tree, runtime/genome/tree/codec.hpp), a control::Controller for a network; either builds its own
// frozen controllers with make_actor again. The factory for every controller that may
// supervise trees (control::ActorFactory).
[[nodiscard]] std::unique_ptr<control::Actor> make_actor(const control::ControllerSpec& spec,
                                                         std::span<const double> genome, int depth);

}  // namespace esc::tree_control
