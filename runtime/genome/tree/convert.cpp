#include "runtime/genome/tree/convert.hpp"

#include <stdexcept>

namespace esc::genome::tree {

namespace {

void emit(const Tree& t, const PrimitiveSet& set, std::size_t i, expr::Program& out) {
  const Node& n = t.nodes[i];
  const Primitive& p = set[n.prim];
  const auto c = children(t, i);
  switch (p.kind) {
    case Kind::Constant:
    case Kind::Erc: out.push_const(n.value); return;
    case Kind::Observable: out.push_load(p.slot); return;
    case Kind::Function:
      for (std::size_t k = 0; k < n.arity; ++k) emit(t, set, c[k], out);
      out.push_op(p.op);
      return;
    default: throw std::invalid_argument("to_expr_program: `" + p.name + "` is not a Number or Bool");
  }
}

void emit_wheel(const Tree& t, const PrimitiveSet& set, std::size_t i, std::size_t w,
                expr::Program& out) {
  const auto c = children(t, i);
  if (set[t.nodes[i].prim].kind == Kind::Wheels) {
    emit(t, set, c[w], out);
    return;
  }
  emit(t, set, c[0], out);
  emit_wheel(t, set, c[1], w, out);
  emit_wheel(t, set, c[2], w, out);
  out.push_op(expr::Op::Select);
}

expr::Program finished(expr::Program p) {
  if (!p.complete())
    throw std::invalid_argument("to_expr_program: the tree needs " + std::to_string(p.max_depth()) +
                                " stack slots, more than an expr::Program has");
  return p;
}

}  // namespace

expr::Program to_expr_program(const Tree& tree, const PrimitiveSet& set, std::size_t i) {
  expr::Program p;
  emit(tree, set, i, p);
  return finished(std::move(p));
}

expr::Program to_wheel_program(const Tree& tree, const PrimitiveSet& set, std::size_t wheel) {
  if (tree.empty() || tree.nodes.back().type != Type::Wheels)
    throw std::invalid_argument("to_wheel_program: the tree's root is not Wheels");
  expr::Program p;
  emit_wheel(tree, set, tree.root(), wheel, p);
  return finished(std::move(p));
}

}  // namespace esc::genome::tree
