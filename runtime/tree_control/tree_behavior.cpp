#include "runtime/tree_control/tree_behavior.hpp"

#include <utility>

#include "runtime/evo/gp/convert.hpp"

namespace esc::tree_control {

control::Behavior to_behavior(const evo::gp::Tree& tree, const evo::gp::PrimitiveSet& set, std::string name) {
  control::Behavior b;
  b.name = std::move(name);
  b.left = evo::gp::to_wheel_program(tree, set, 0);
  b.right = evo::gp::to_wheel_program(tree, set, 1);
  return b;
}

}  // namespace esc::tree_control
