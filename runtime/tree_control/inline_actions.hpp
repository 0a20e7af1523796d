#pragma once
// An Action tree as the Wheels tree that computes the same wheel commands, so that it
// prints as a behavior (evo/gp/print.hpp's behavior_script) that can be pasted into a script and
// scores exactly what the tree scores. Each action node becomes its behavior's
// wheels(LEFT, RIGHT) with the action's parameter subtrees in place of the parameters,
// and if-then-else over actions becomes if-then-else over wheels. The arithmetic is the
// same operation for operation: the parameters are the same subtrees, and the behaviors'
// programs use expr::Program's operators, which GP trees share (semantics.hpp).
//
// The result is a tree over a new primitive set: the old primitives with their ids, then
// what the behaviors' programs need (their operators taking and giving Numbers, the
// observables they read, a holder for their constants), wheels and if-then-else over
// wheels. A condition that is a number, not a comparison, becomes `c != 0`, which selects
// the same branch.
#include <span>

#include "runtime/control/behavior.hpp"
#include "runtime/genome/tree/tree.hpp"

namespace esc::tree_control {

struct InlinedTree {
  genome::tree::PrimitiveSet set;
  genome::tree::Tree tree;
};

// `actions[k]` is the behavior of the Action primitives with index k. Throws
// std::invalid_argument if the tree is not a well-typed Action tree of `set`, an index or a
// parameter count does not match `actions`, or a behavior reads a slot that has no name
// in scripts on its own (`in(zone)`, `reached(light)`: their names belong to an arena).
[[nodiscard]] InlinedTree inline_actions(const genome::tree::Tree& tree, const genome::tree::PrimitiveSet& set,
                                         std::span<const control::Behavior> actions);

}  // namespace esc::tree_control
