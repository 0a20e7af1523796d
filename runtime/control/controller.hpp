#pragma once
// A controller ready to drive: a ControllerSpec bound to one genome, with its own
// working buffers, so step() does not allocate. Build one per evaluation, or build one
// per worker and rebind() it to each genome in turn.
//
// A supervisor owns one Actor per supervised sub-controller (built with it, bound to the
// fixed genome stored in the spec), each with its own buffers and recurrent state: a
// Controller for a network, or whatever the ActorFactory it was given builds (a tree).
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <variant>
#include <vector>

#include "runtime/control/actor.hpp"
#include "runtime/control/controller_spec.hpp"
#include "runtime/control/graph_net.hpp"
#include "runtime/control/mlp.hpp"

namespace esc::control {

// How a head activates its network's outputs: tanh for the classical head's wheel commands,
// the logistic for the symbolic head's and the supervisor's choices and parameters.
[[nodiscard]] Activation output_activation(Head head) noexcept;

class Controller final : public Actor {
 public:
  // Supervisors may supervise supervisors, down to this depth (a deeper chain is almost
  // certainly a spec that contains itself).
  static constexpr int kMaxNesting = 8;

  // `genome` must have spec.genome_size() values (a `neat(...)` network's: be a graph genome
  // of its inputs and outputs); both must outlive the controller.
  // Throws std::invalid_argument on a wrong genome size or a spec the controller cannot
  // run (symbolic head without actions, an action with more than expr::kMaxParams
  // parameters or an incomplete program, an input slot outside the frame, an Elman
  // network without exactly one hidden layer, a supervisor without behaviors, a behavior
  // call with the wrong number of arguments, a sub-controller whose spec is missing or
  // whose genome has the wrong size, a frozen tree without a factory to build it, ...).
  Controller(const ControllerSpec& spec, std::span<const double> genome);
  // Frozen sub-controllers (a supervisor's evolved behaviors) are built by `subs`, `depth`
  // levels below the top controller (ActorFactory); without one, only networks can be.
  Controller(const ControllerSpec& spec, std::span<const double> genome, ActorFactory subs, int depth = 0);

  // Points the controller at another genome of the same size, keeping its buffers (a graph
  // genome's network is built anew), then
  // resets it and clears its usage counts (a new genome is a new individual).
  // Sub-controllers keep their fixed genomes. Throws std::invalid_argument on a wrong size.
  void rebind(std::span<const double> genome);

  // Clears all internal state, sub-controllers' included: Elman context units, last
  // action (called at the start of each epoch). Usage counts are kept.
  void reset() noexcept override;

  // Reads the inputs from `frame`, runs the network and the head. A symbolic head writes
  // the chosen action's parameters into frame[slot::param + i] before running it; a
  // supervisor writes a behavior call's arguments there, or steps the chosen
  // sub-controller, which may write its own parameters there.
  WheelCommand step(expr::Frame& frame) noexcept override;

  // The head alone on `outputs`, activated outputs of a network of this spec's shape
  // (output_count() values) in place of its own: what step() does after running the network.
  // For a caller that runs the network itself (the Python module's Env takes a policy's
  // outputs as its actions); the controller's own network is not used.
  WheelCommand act(std::span<const double> outputs, expr::Frame& frame) noexcept;

  // Index of the action (symbolic head) or behavior (supervisor) chosen by the last step;
  // -1 for a classical head or before the first step after a reset.
  [[nodiscard]] int last_action() const noexcept override { return last_action_; }

  // Steps spent in each action (symbolic) or behavior (supervisor), in spec order (see
  // ControllerSpec::choice_names()), since construction, rebind() or clear_usage();
  // empty for a classical head.
  [[nodiscard]] std::span<const std::int64_t> usage() const noexcept override { return usage_; }
  // Zeroes the usage counts, sub-controllers' included.
  void clear_usage() noexcept override;

  // Supervisor: the controller running behavior `i` if it is a sub-controller (its own
  // last_action() and usage() tell what it did); nullptr for a behavior call, an index out
  // of range, or another head.
  [[nodiscard]] const Actor* sub_controller(std::size_t i) const noexcept;

  [[nodiscard]] const ControllerSpec& spec() const noexcept { return *spec_; }

 private:
  // The head on outputs `output(i)` (activated, asked for only where read).
  template <class Outputs>
  WheelCommand head(const Outputs& output, expr::Frame& frame) noexcept;

  const ControllerSpec* spec_;
  std::variant<Mlp, GraphNet> net_;
  std::vector<std::size_t> param_offset_;  // symbolic head: output index of action i's param 0
  std::vector<std::unique_ptr<Actor>> subs_;   // supervisor: one per FixedController, in order
  std::vector<int> sub_index_;             // supervisor: behavior i's index in subs_, or -1
  std::vector<std::int64_t> usage_;
  int last_action_ = -1;
};

}  // namespace esc::control
