#pragma once
// A controller ready to drive: a ControllerSpec bound to one genome, with its own
// working buffers, so step() does not allocate. Build one per evaluation, or build one
// per worker and rebind() it to each genome in turn.
#include <cstddef>
#include <span>
#include <vector>

#include "runtime/control/controller_spec.hpp"
#include "runtime/control/mlp.hpp"

namespace esc::control {

class Controller {
 public:
  // `genome` must have spec.genome_size() values; both must outlive the controller.
  // Throws std::invalid_argument on a wrong genome size or a spec the controller cannot
  // run (symbolic head without actions, an action with more than expr::kMaxParams
  // parameters or an incomplete program, an input slot outside the frame, ...).
  Controller(const ControllerSpec& spec, std::span<const double> genome);

  // Points the controller at another genome of the same size, keeping its buffers, and
  // resets it. Throws std::invalid_argument on a wrong size.
  void rebind(std::span<const double> genome);

  // Clears any internal state (called at the start of each epoch).
  void reset() noexcept;

  // Reads the inputs from `frame`, runs the network and the head. A symbolic head writes
  // the chosen action's parameters into frame[slot::param + i] before running it.
  WheelCommand step(expr::Frame& frame) noexcept;

  // Index of the action chosen by the last step (symbolic head), else -1.
  [[nodiscard]] int last_action() const noexcept { return last_action_; }

  [[nodiscard]] const ControllerSpec& spec() const noexcept { return *spec_; }

 private:
  const ControllerSpec* spec_;
  Mlp net_;
  std::vector<std::size_t> param_offset_;  // symbolic head: output index of action i's param 0
  int last_action_ = -1;
};

}  // namespace esc::control
