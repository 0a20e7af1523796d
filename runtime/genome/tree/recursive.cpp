#include "runtime/genome/tree/recursive.hpp"

#include "runtime/genome/tree/semantics.hpp"

namespace esc::genome::tree {

namespace {

// Action, Behavior and Wheels subtrees write `out`.
void effect(const Tree& t, const PrimitiveSet& set, std::span<const double> frame, std::size_t i,
            Output& out) noexcept {
  const Node& n = t.nodes[i];
  const Primitive& p = set[n.prim];
  const auto c = children(t, i);
  switch (p.kind) {
    case Kind::Action:
      for (std::size_t k = 0; k < n.arity; ++k) out.params[k] = evaluate_number(t, set, frame, c[k]);
      out.param_count = n.arity;
      out.index = static_cast<std::int32_t>(p.index);
      return;
    case Kind::Behavior: out.index = static_cast<std::int32_t>(p.index); return;
    case Kind::Wheels:
      out.left = evaluate_number(t, set, frame, c[0]);
      out.right = evaluate_number(t, set, frame, c[1]);
      return;
    default:  // if-then-else
      effect(t, set, frame, evaluate_number(t, set, frame, c[0]) != 0.0 ? c[1] : c[2], out);
      return;
  }
}

}  // namespace

double evaluate_number(const Tree& t, const PrimitiveSet& set, std::span<const double> frame,
                       std::size_t i) noexcept {
  const Node& n = t.nodes[i];
  const Primitive& p = set[n.prim];
  switch (p.kind) {
    case Kind::Constant:
    case Kind::Erc: return n.value;
    case Kind::Observable: return frame[p.slot];
    default: break;
  }
  const auto c = children(t, i);
  switch (n.arity) {
    case 1: return sem::unary(p.op, evaluate_number(t, set, frame, c[0]));
    case 2: {
      const double a = evaluate_number(t, set, frame, c[0]);
      return sem::binary(p.op, a, evaluate_number(t, set, frame, c[1]));
    }
    default: {
      const double x = evaluate_number(t, set, frame, c[0]);
      if (p.op == expr::Op::Select) return evaluate_number(t, set, frame, x != 0.0 ? c[1] : c[2]);
      const double lo = evaluate_number(t, set, frame, c[1]);
      return sem::clamp(x, lo, evaluate_number(t, set, frame, c[2]));
    }
  }
}

Output evaluate_recursive(const Tree& tree, const PrimitiveSet& set,
                          std::span<const double> frame) noexcept {
  Output out;
  const Type t = tree.nodes.back().type;
  if (t == Type::Number || t == Type::Bool) out.value = evaluate_number(tree, set, frame, tree.root());
  else effect(tree, set, frame, tree.root(), out);
  return out;
}

}  // namespace esc::genome::tree
