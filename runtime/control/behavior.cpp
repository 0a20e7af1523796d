#include "runtime/control/behavior.hpp"

#include <algorithm>
#include <cmath>

namespace esc::control {

namespace {

// Wheel commands live in [-1, 1]. Programs are total, so NaN should never appear; should
// one slip through, the wheel stops rather than spinning at full speed.
inline double clamp_unit(double v) noexcept {
  if (std::isnan(v)) return 0.0;
  return std::clamp(v, -1.0, 1.0);
}

}  // namespace

WheelCommand run_behavior(const Behavior& b, const expr::Frame& frame) noexcept {
  return {clamp_unit(b.left.eval(frame)), clamp_unit(b.right.eval(frame))};
}

}  // namespace esc::control
