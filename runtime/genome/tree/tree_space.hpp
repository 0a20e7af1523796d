#pragma once
// What an optimizer is told about the trees it evolves (evo::Problem::tree): the primitive
// set they are built of (the tree controller's) and how they are varied (the experiment's
// `evolve gp(...)`). Both null for another kind of genome; operators null when the
// experiment gives none (an algorithm over trees then names what is missing: tree_problem).
namespace esc::genome::tree {

class PrimitiveSet;
struct TreeOperators;

struct TreeSpace {
  const PrimitiveSet* primitives = nullptr;
  const TreeOperators* operators = nullptr;
};

}  // namespace esc::genome::tree
