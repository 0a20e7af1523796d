#pragma once
// A controller ready to drive: a ControllerSpec bound to one genome, with its own
// working buffers, so step() does not allocate. One instance per evaluation.
#include <span>
#include <vector>

#include <Eigen/Core>

#include "runtime/control/controller_spec.hpp"

namespace esc::control {

class Controller {
 public:
  // `genome` must have spec.genome_size() values; both must outlive the controller.
  Controller(const ControllerSpec& spec, std::span<const double> genome);

  // Clears any internal state (called at the start of each epoch).
  void reset() noexcept;

  // Reads the inputs from `frame`, runs the network and the head. A symbolic head writes
  // the chosen action's parameters into frame[slot::param + i] before running it.
  WheelCommand step(expr::Frame& frame) noexcept;

  // Index of the action chosen by the last step (symbolic head), else -1.
  [[nodiscard]] int last_action() const noexcept { return last_action_; }

 private:
  const ControllerSpec* spec_;
  std::vector<Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>> layers_;
  std::vector<Eigen::VectorXd> activations_;  // one buffer per layer, input first, bias slot last
  int last_action_ = -1;
};

}  // namespace esc::control
