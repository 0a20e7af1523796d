#include "runtime/tree_control/tree_behavior.hpp"

#include <utility>

#include "runtime/genome/tree/convert.hpp"

namespace esc::tree_control {

control::Behavior to_behavior(const genome::tree::Tree& tree, const genome::tree::PrimitiveSet& set, std::string name) {
  control::Behavior b;
  b.name = std::move(name);
  b.left = genome::tree::to_wheel_program(tree, set, 0);
  b.right = genome::tree::to_wheel_program(tree, set, 1);
  return b;
}

}  // namespace esc::tree_control
