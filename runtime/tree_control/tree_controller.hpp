#pragma once
// A GP tree driving the robot, with the shape of control::Controller: built from a spec and
// one genome (here a tree), reset() per epoch, step(frame) per control step without
// allocation, last_action(). The spec's primitive set decides the use by its root type:
//   Wheels:   a tree controller; the tree gives both wheel commands, clamped to [-1, 1]
//             (NaN stops the wheel), exactly as a behavior's wheels(...) is applied;
//   Action:   the GP twin of the paper's symbolic controller; the tree picks action k of
//             `actions` with its parameters, which are written to frame[slot::param + i]
//             before the action's behavior runs (so an action primitive must take as many
//             parameters as its behavior declares);
//   Behavior: a tree supervisor; the tree picks delegate k of `behaviors`, which acts.
// The compiler builds the spec once per experiment; the evaluation loop builds one
// TreeController per worker and rebind()s it to each tree.
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "runtime/control/behavior.hpp"
#include "runtime/genome/tree/program.hpp"

namespace esc::tree_control {

// What a supervisor's tree can choose: a behavior run with fixed parameters, or (the hook
// for supervising arbitrary controllers) a callable. `step` is called instead of the
// behavior when set, and `reset` (if set) at every TreeController::reset(). Neither may
// allocate in step.
struct Delegate {
  std::string name;
  control::Behavior behavior;
  std::array<double, expr::kMaxParams> params{};  // behavior.params.size() of them are used
  std::function<control::WheelCommand(expr::Frame&)> step;
  std::function<void()> reset;
};

struct TreeControllerSpec {
  std::string name;
  genome::tree::PrimitiveSet primitives;   // root(): Wheels, Action or Behavior
  std::vector<control::Behavior> actions;      // Action root: Action primitive with index k runs actions[k]
  std::vector<Delegate> behaviors;    // Behavior root: Behavior primitive index k runs behaviors[k]
};

class TreeController {
 public:
  // Throws std::invalid_argument when the spec cannot run (a root type other than Wheels,
  // Action or Behavior; an action or behavior index outside its list; an action whose
  // parameter count differs from its behavior's; an incomplete behavior program) or the
  // tree is not a well-typed tree of the root type. The spec must outlive the controller.
  TreeController(const TreeControllerSpec& spec, const genome::tree::Tree& tree);

  // Compiles another tree (allocates) and resets.
  void rebind(const genome::tree::Tree& tree);

  void reset() noexcept;

  control::WheelCommand step(expr::Frame& frame) noexcept;

  // Index of the action or delegate chosen by the last step; -1 for a Wheels tree or before
  // the first step.
  [[nodiscard]] int last_action() const noexcept { return last_action_; }

  [[nodiscard]] const TreeControllerSpec& spec() const noexcept { return *spec_; }
  [[nodiscard]] const genome::tree::FlatProgram& program() const noexcept { return program_; }

 private:
  const TreeControllerSpec* spec_;
  genome::tree::FlatProgram program_;
  genome::tree::FlatProgram::Stack stack_{};
  int last_action_ = -1;
};

}  // namespace esc::tree_control
