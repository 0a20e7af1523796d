#pragma once
// A Wheels tree as the behavior its printed form is (evo/gp/print.hpp's behavior_script):
// what the compiler makes of the pasted text, up to constant folding, so it computes the
// tree's wheel commands bit for bit. Here rather than in evo/gp because a behavior is a
// controller's object (esc_control); the GP engine itself needs only expressions.
#include <string>

#include "runtime/control/behavior.hpp"
#include "runtime/genome/tree/tree.hpp"

namespace esc::tree_control {

// A behavior with no parameters. Throws std::invalid_argument if the root is not Wheels or a
// wheel's program would not fit expr::Program's stack.
[[nodiscard]] control::Behavior to_behavior(const genome::tree::Tree& tree, const genome::tree::PrimitiveSet& set,
                                            std::string name);

}  // namespace esc::tree_control
