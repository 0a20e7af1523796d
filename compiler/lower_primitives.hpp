#pragma once
// Lowers `primitives` declarations (the functions and terminals GP trees are made of) and
// gives each `tree(...)` controller its primitive set: the declaration's primitives plus
// what the tree's result adds (wheels, the actions, the behaviors, if-then-else over it).
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "compiler/ast.hpp"
#include "compiler/resolver.hpp"
#include "compiler/sink.hpp"
#include "runtime/control/controller_spec.hpp"
#include "runtime/genome/tree/primitive_set.hpp"

namespace esc::compiler {

struct PrimitiveList {
  std::vector<genome::tree::Primitive> items;
  bool branches = false;   // `if` is listed
};

class PrimitivesLowering {
 public:
  PrimitivesLowering(Sink& sink, Resolver& names) : sink_(sink), names_(names) {}

  // Memoised; null when the declaration is wrong (reported).
  const std::optional<PrimitiveList>& lower(const ast::PrimitivesDecl& d);
  // Gives `c` (its head, actions and behaviors lowered) the primitive set of `tree(...)`;
  // false when that fails (reported).
  bool tree(const ast::ControllerDecl& d, control::ControllerSpec& c);

 private:
  Sink& sink_;
  Resolver& names_;
  std::map<const ast::PrimitivesDecl*, std::optional<PrimitiveList>> lists_;
  std::set<std::string> reported_sets_;   // unbuildable (set, root) pairs already reported
};

}  // namespace esc::compiler
