#pragma once
// Behaviors of the standard library, built by hand the way the compiler builds them.
#include <cstdint>
#include <string>
#include <vector>

#include "runtime/control/behavior.hpp"
#include "runtime/expr/observables.hpp"

namespace esc::control::testing {

inline expr::Program param(std::uint32_t k, bool negate = false) {
  expr::Program p;
  p.push_load(expr::slot::param + k);
  if (negate) p.push_op(expr::Op::Neg);
  return p;
}

// behavior forward(p) { wheels(p, p) }
inline Behavior forward() { return {"forward", {"p"}, param(0), param(0)}; }
// behavior left(p) { wheels(-p, p) }
inline Behavior left() { return {"left", {"p"}, param(0, true), param(0)}; }
// behavior right(p) { wheels(p, -p) }
inline Behavior right() { return {"right", {"p"}, param(0), param(0, true)}; }
// behavior backward(p) { wheels(-p, -p) }
inline Behavior backward() { return {"backward", {"p"}, param(0, true), param(0, true)}; }
// behavior stop() { wheels(0, 0) }
inline Behavior stop() {
  return {"stop", {}, expr::Program::constant(0.0), expr::Program::constant(0.0)};
}
// behavior spin(a, b) { wheels(a, -b) }
inline Behavior spin() { return {"spin", {"a", "b"}, param(0), param(1, true)}; }

inline std::vector<expr::Slot> ir_inputs() {
  std::vector<expr::Slot> in;
  for (expr::Slot i = 0; i < expr::kIrCount; ++i) in.push_back(expr::slot::ir + i);
  return in;
}

// Seventeen inputs, like the paper's 8 IR + 8 light + energy, taken as raw slots 0..16
// (the light and energy observables are not needed to test the networks).
inline std::vector<expr::Slot> seventeen_inputs() {
  std::vector<expr::Slot> in;
  for (expr::Slot i = 0; i < 17; ++i) in.push_back(i);
  return in;
}

}  // namespace esc::control::testing
