#pragma once
// A behavior written in a script: named parameters and one expression per wheel, e.g.
// `behavior left(p) { wheels(-p, p) }`. The symbolic actions FORWARD, LEFT, RIGHT and
// BACKWARD are behaviors of the standard library script, not C++.
#include <string>
#include <vector>

#include "runtime/expr/observables.hpp"
#include "runtime/expr/program.hpp"

namespace esc::control {

struct Behavior {
  std::string name;
  std::vector<std::string> params;  // read by the programs from slots param[0..]
  expr::Program left;               // wheel commands, clamped to [-1, 1] when applied
  expr::Program right;
};

struct WheelCommand {
  double left = 0.0;
  double right = 0.0;
};

// Evaluates `b` with its parameters already stored in frame[slot::param + i].
[[nodiscard]] WheelCommand run_behavior(const Behavior& b, const expr::Frame& frame) noexcept;

}  // namespace esc::control
