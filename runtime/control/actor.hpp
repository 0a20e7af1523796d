#pragma once
// What a supervisor delegates to when it picks an evolved behavior: a frozen controller that
// drives the wheels one control step at a time. A network (control::Controller) is one; a
// GP tree (tree_control::TreeDriver) is another, built above this layer, so a supervisor
// builds its frozen controllers through an ActorFactory that the layer knowing both kinds
// supplies (tree_control::make_actor). Networks alone need no factory.
#include <cstdint>
#include <memory>
#include <span>

#include "runtime/control/behavior.hpp"

namespace esc::control {

struct ControllerSpec;

class Actor {
 public:
  virtual ~Actor() = default;
  Actor() = default;
  Actor(const Actor&) = delete;
  Actor& operator=(const Actor&) = delete;
  Actor(Actor&&) = default;
  Actor& operator=(Actor&&) = default;

  // Clears the recurrent state (start of an epoch); usage counts are kept.
  virtual void reset() noexcept = 0;
  // One control step; must not allocate.
  virtual WheelCommand step(expr::Frame& frame) noexcept = 0;
  // Index of the action or behavior chosen by the last step; -1 when it chooses none.
  [[nodiscard]] virtual int last_action() const noexcept = 0;
  // Steps spent in each action or behavior since it was built or its usage cleared.
  [[nodiscard]] virtual std::span<const std::int64_t> usage() const noexcept = 0;
  virtual void clear_usage() noexcept = 0;
};

// Builds the actor that runs `spec` with `genome` (network weights, or an encoded tree),
// `depth` levels of supervision below the top controller. Throws std::invalid_argument when
// it cannot run.
using ActorFactory = std::unique_ptr<Actor> (*)(const ControllerSpec& spec, std::span<const double> genome, int depth);

}  // namespace esc::control
