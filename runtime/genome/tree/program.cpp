#include "runtime/genome/tree/program.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

#include "runtime/genome/tree/semantics.hpp"

namespace esc::genome::tree {

namespace {

static_assert(static_cast<int>(Code::Const) == static_cast<int>(expr::Op::Const));
static_assert(static_cast<int>(Code::Load) == static_cast<int>(expr::Op::Load));
static_assert(static_cast<int>(Code::Sigmoid) == static_cast<int>(expr::Op::Sigmoid));
static_assert(static_cast<int>(Code::Add) == static_cast<int>(expr::Op::Add));
static_assert(static_cast<int>(Code::Or) == static_cast<int>(expr::Op::Or));
static_assert(static_cast<int>(Code::Clamp) == static_cast<int>(expr::Op::Clamp));
static_assert(static_cast<int>(Code::Unused) == static_cast<int>(expr::Op::Select));

class Compiler {
 public:
  Compiler(const Tree& t, const PrimitiveSet& set) : t_(t), set_(set) {}

  void emit(std::size_t i) {
    const Node& n = t_.nodes[i];
    const Primitive& p = set_[n.prim];
    const auto c = children(t_, i);
    switch (p.kind) {
      case Kind::Constant:
      case Kind::Erc: push({Code::Const, 0, 0, n.value}, +1); return;
      case Kind::Observable: push({Code::Load, 0, p.slot, 0.0}, +1); return;
      case Kind::Behavior: push({Code::Behavior, 0, p.index, 0.0}, 0); return;
      case Kind::Action:
        for (std::size_t k = 0; k < n.arity; ++k) emit(c[k]);
        push({Code::Action, n.arity, p.index, 0.0}, -static_cast<int>(n.arity));
        return;
      case Kind::Wheels:
        emit(c[0]);
        emit(c[1]);
        push({Code::Wheels, 0, 0, 0.0}, -2);
        return;
      case Kind::Function: break;
    }
    if (p.op == expr::Op::Select) {
      emit(c[0]);
      const std::size_t jz = code_.size();
      push({Code::JumpIfZero, 0, 0, 0.0}, -1);
      const std::size_t depth_before = depth_;
      emit(c[1]);
      const std::size_t jmp = code_.size();
      push({Code::Jump, 0, 0, 0.0}, 0);
      code_[jz].arg = static_cast<std::uint32_t>(code_.size());
      depth_ = depth_before;  // the else branch starts from the same stack
      emit(c[2]);
      code_[jmp].arg = static_cast<std::uint32_t>(code_.size());
      return;
    }
    for (std::size_t k = 0; k < n.arity; ++k) emit(c[k]);
    push({static_cast<Code>(p.op), 0, 0, 0.0}, 1 - static_cast<int>(n.arity));
  }

  std::vector<Instr> code_;
  std::size_t depth_ = 0, max_ = 0;

 private:
  void push(Instr in, int delta) {
    code_.push_back(in);
    depth_ = static_cast<std::size_t>(static_cast<int>(depth_) + delta);
    max_ = std::max(max_, depth_);
  }
  const Tree& t_;
  const PrimitiveSet& set_;
};

const char* name_of(Code c) noexcept {
  constexpr std::array names = {"const", "load", "neg", "not", "abs", "sqrt", "exp", "log",
                                "tanh", "sigmoid", "add", "sub", "mul", "div", "pow", "min",
                                "max", "lt", "le", "gt", "ge", "eq", "ne", "and", "or",
                                "clamp", "unused", "jz", "jmp", "action", "behavior", "wheels"};
  return names[static_cast<std::size_t>(c)];
}

}  // namespace

FlatProgram compile(const Tree& tree, const PrimitiveSet& set) {
  if (tree.empty()) throw std::invalid_argument("gp compile: empty tree");
  const Type root = tree.nodes.back().type;
  if (const std::string why = check(tree, set, root); !why.empty())
    throw std::invalid_argument("gp compile: ill-typed tree: " + why);
  Compiler c(tree, set);
  c.emit(tree.root());
  if (c.max_ > FlatProgram::kMaxStack)
    throw std::invalid_argument(fmt::format("gp compile: the tree needs {} stack slots, at most {}",
                                            c.max_, FlatProgram::kMaxStack));
  FlatProgram p;
  p.code_ = std::move(c.code_);
  p.type_ = root;
  p.max_stack_ = c.max_;
  return p;
}

Output FlatProgram::run(std::span<const double> frame, Stack& stack) const noexcept {
  Output out;
  double* s = stack.data();
  std::size_t top = 0;
  const Instr* code = code_.data();
  const std::size_t n = code_.size();
  for (std::size_t pc = 0; pc < n; ++pc) {
    const Instr& in = code[pc];
    switch (in.code) {
      case Code::Const: s[top++] = in.value; break;
      case Code::Load: s[top++] = frame[in.arg]; break;
      case Code::Neg: case Code::Not: case Code::Abs: case Code::Sqrt: case Code::Exp:
      case Code::Log: case Code::Tanh: case Code::Sigmoid:
        s[top - 1] = sem::unary(static_cast<expr::Op>(in.code), s[top - 1]);
        break;
      case Code::Add: --top; s[top - 1] = sem::finite(s[top - 1] + s[top]); break;
      case Code::Sub: --top; s[top - 1] = sem::finite(s[top - 1] - s[top]); break;
      case Code::Mul: --top; s[top - 1] = sem::finite(s[top - 1] * s[top]); break;
      case Code::Div:
      case Code::Pow: case Code::Min: case Code::Max: case Code::Lt: case Code::Le:
      case Code::Gt: case Code::Ge: case Code::Eq: case Code::Ne: case Code::And: case Code::Or:
        --top;
        s[top - 1] = sem::binary(static_cast<expr::Op>(in.code), s[top - 1], s[top]);
        break;
      case Code::Clamp:
        top -= 2;
        s[top - 1] = sem::clamp(s[top - 1], s[top], s[top + 1]);
        break;
      case Code::JumpIfZero:
        if (s[--top] == 0.0) pc = in.arg - 1;  // the loop's ++pc lands on the target
        break;
      case Code::Jump: pc = in.arg - 1; break;
      case Code::Action:
        top -= in.count;
        for (std::size_t k = 0; k < in.count; ++k) out.params[k] = s[top + k];
        out.param_count = in.count;
        out.index = static_cast<std::int32_t>(in.arg);
        break;
      case Code::Behavior: out.index = static_cast<std::int32_t>(in.arg); break;
      case Code::Wheels:
        top -= 2;
        out.left = s[top];
        out.right = s[top + 1];
        break;
      case Code::Unused: break;
    }
  }
  if (top == 1) out.value = s[0];
  return out;
}

std::string FlatProgram::disassemble() const {
  std::string out;
  for (std::size_t pc = 0; pc < code_.size(); ++pc) {
    const Instr& in = code_[pc];
    out += fmt::format("{}: {}", pc, name_of(in.code));
    switch (in.code) {
      case Code::Const: out += fmt::format(" {}", in.value); break;
      case Code::Load: case Code::JumpIfZero: case Code::Jump: case Code::Behavior:
        out += fmt::format(" {}", in.arg);
        break;
      case Code::Action: out += fmt::format(" {} ({} params)", in.arg, in.count); break;
      default: break;
    }
    out += '\n';
  }
  return out;
}

}  // namespace esc::genome::tree
