#include "runtime/genome/tree/print.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace esc::genome::tree {

namespace {

using expr::Op;

// Precedence levels of docs/language.md: 1 binds tightest, 10 loosest.
constexpr int kAtom = 1, kPow = 2, kUnary = 3, kNot = 7, kIf = 10;

struct Text {
  std::string s;
  int prec = kAtom;
};

std::string paren(const Text& t, bool need) { return need ? fmt::format("({})", t.s) : t.s; }

int level(Op op) noexcept {
  switch (op) {
    case Op::Pow: return kPow;
    case Op::Mul: case Op::Div: return 4;
    case Op::Add: case Op::Sub: return 5;
    case Op::Lt: case Op::Le: case Op::Gt: case Op::Ge: case Op::Eq: case Op::Ne: return 6;
    case Op::And: return 8;
    case Op::Or: return 9;
    default: return 0;  // a call
  }
}

const char* infix(Op op) noexcept {
  switch (op) {
    case Op::Pow: return "^";
    case Op::Mul: return "*";
    case Op::Div: return "/";
    case Op::Add: return "+";
    case Op::Sub: return "-";
    case Op::Lt: return "<";
    case Op::Le: return "<=";
    case Op::Gt: return ">";
    case Op::Ge: return ">=";
    case Op::Eq: return "==";
    case Op::Ne: return "!=";
    case Op::And: return "and";
    case Op::Or: return "or";
    default: return "?";
  }
}

const char* call_name(Op op) noexcept {
  switch (op) {
    case Op::Abs: return "abs";
    case Op::Sqrt: return "sqrt";
    case Op::Exp: return "exp";
    case Op::Log: return "log";
    case Op::Tanh: return "tanh";
    case Op::Sigmoid: return "sigmoid";
    case Op::Min: return "min";
    case Op::Max: return "max";
    case Op::Clamp: return "clamp";
    default: return "?";
  }
}

class Printer {
 public:
  Printer(const Tree& t, const PrimitiveSet& set) : t_(t), set_(set) {}

  Text value(std::size_t i) const {
    const Node& n = t_.nodes[i];
    const Primitive& p = set_[n.prim];
    switch (p.kind) {
      case Kind::Constant:
        if (p.result == Type::Bool) return {n.value != 0.0 ? "true" : "false", kAtom};
        [[fallthrough]];
      case Kind::Erc: return {number_text(n.value), std::signbit(n.value) ? kUnary : kAtom};
      case Kind::Observable: return {p.name, kAtom};
      case Kind::Function: break;
      default: return {"?", kAtom};
    }
    const auto c = children(t_, i);
    if (p.op == Op::Select) return if_text(value(c[0]), value(c[1]), value(c[2]));
    if (p.op == Op::Neg) {
      const Text a = value(c[0]);
      return {fmt::format("-{}", paren(a, a.prec > kPow)), kUnary};
    }
    if (p.op == Op::Not) {
      const Text a = value(c[0]);
      return {fmt::format("not {}", paren(a, a.prec > kNot)), kNot};
    }
    const int l = level(p.op);
    if (l == 0) {
      std::string s = fmt::format("{}(", call_name(p.op));
      for (std::size_t k = 0; k < n.arity; ++k) s += fmt::format("{}{}", k > 0 ? ", " : "", value(c[k]).s);
      return {s + ")", kAtom};
    }
    const Text a = value(c[0]), b = value(c[1]);
    if (p.op == Op::Pow)  // right-associative; operands other than atoms get parentheses
      return {fmt::format("{} ^ {}", paren(a, a.prec >= kPow), paren(b, b.prec > kPow)), kPow};
    return {fmt::format("{} {} {}", paren(a, a.prec > l), infix(p.op), paren(b, b.prec >= l)), l};
  }

  static Text if_text(const Text& c, const Text& a, const Text& b) {
    return {fmt::format("if {} then {} else {}", paren(c, c.prec >= kIf), paren(a, a.prec >= kIf), b.s),
            kIf};
  }

  // Wheel w (0 left, 1 right) of a Wheels subtree.
  Text wheel(std::size_t i, std::size_t w) const {
    const auto c = children(t_, i);
    if (set_[t_.nodes[i].prim].kind == Kind::Wheels) return value(c[w]);
    return if_text(value(c[0]), wheel(c[1], w), wheel(c[2], w));
  }

  // Action or Behavior subtree.
  Text choice(std::size_t i) const {
    const Node& n = t_.nodes[i];
    const Primitive& p = set_[n.prim];
    const auto c = children(t_, i);
    if (p.kind == Kind::Behavior) return {p.name, kAtom};
    if (p.kind == Kind::Action) {
      std::string s = fmt::format("{}(", p.name);
      for (std::size_t k = 0; k < n.arity; ++k) s += fmt::format("{}{}", k > 0 ? ", " : "", value(c[k]).s);
      return {s + ")", kAtom};
    }
    return if_text(value(c[0]), choice(c[1]), choice(c[2]));
  }

 private:
  const Tree& t_;
  const PrimitiveSet& set_;
};

}  // namespace

std::string number_text(double v) { return fmt::format("{}", v); }

std::string expression(const Tree& tree, const PrimitiveSet& set, std::size_t i) {
  return Printer(tree, set).value(i).s;
}

std::string to_script(const Tree& tree, const PrimitiveSet& set) {
  const Printer p(tree, set);
  switch (tree.nodes.back().type) {
    case Type::Number:
    case Type::Bool: return p.value(tree.root()).s;
    case Type::Wheels:
      return fmt::format("wheels({}, {})", p.wheel(tree.root(), 0).s, p.wheel(tree.root(), 1).s);
    case Type::Action:
    case Type::Behavior: return p.choice(tree.root()).s;
  }
  return {};
}

std::string behavior_script(const Tree& tree, const PrimitiveSet& set, std::string_view name) {
  if (tree.empty() || tree.nodes.back().type != Type::Wheels)
    throw std::invalid_argument("behavior_script: the tree's root is not Wheels");
  return fmt::format("behavior {}() {{ {} }}", name, to_script(tree, set));
}

}  // namespace esc::genome::tree
