#include "runtime/expr/program.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace esc::expr {

int arity(Op op) noexcept {
  switch (op) {
    case Op::Const:
    case Op::Load: return 0;
    case Op::Neg: case Op::Not: case Op::Abs: case Op::Sqrt: case Op::Exp:
    case Op::Log: case Op::Tanh: case Op::Sigmoid: return 1;
    case Op::Clamp:
    case Op::Select: return 3;
    default: return 2;
  }
}

namespace {

const char* name_of(Op op) noexcept {
  constexpr std::array names = {"const", "load", "neg", "not", "abs", "sqrt", "exp", "log",
                                "tanh", "sigmoid", "add", "sub", "mul", "div", "pow", "min",
                                "max", "lt", "le", "gt", "ge", "eq", "ne", "and", "or",
                                "clamp", "select"};
  return names[static_cast<std::size_t>(op)];
}

// Finite results for finite inputs: overflow saturates instead of reaching infinity.
inline double finite(double v) noexcept {
  if (std::isnan(v)) return 0.0;
  return std::clamp(v, -kSaturation, kSaturation);
}

}  // namespace

Program Program::constant(double v) {
  Program p;
  p.push_const(v);
  return p;
}

void Program::push_const(double v) {
  code_.push_back({Op::Const, 0, v});
  max_depth_ = std::max(max_depth_, ++depth_);
}

void Program::push_load(std::uint32_t slot) {
  code_.push_back({Op::Load, slot, 0.0});
  max_depth_ = std::max(max_depth_, ++depth_);
}

void Program::push_op(Op op) {
  const auto n = static_cast<std::size_t>(arity(op));
  if (n == 0) throw std::logic_error("push_op takes operators; use push_const or push_load");
  if (depth_ < n) throw std::logic_error(fmt::format("'{}' needs {} operands", name_of(op), n));
  code_.push_back({op, 0, 0.0});
  depth_ -= n - 1;
}

double Program::eval(std::span<const double> frame) const noexcept {
  // A lone observable or constant (a stop condition, an action's `p`): no stack to fill.
  if (code_.size() == 1) return code_[0].op == Op::Load ? frame[code_[0].slot] : code_[0].value;
  std::array<double, kMaxStack> s;  // NOLINT: filled before read
  std::size_t top = 0;              // number of values on the stack
  for (const Instr& in : code_) {
    switch (in.op) {
      case Op::Const: s[top++] = in.value; break;
      case Op::Load: s[top++] = frame[in.slot]; break;
      case Op::Neg: s[top - 1] = -s[top - 1]; break;
      case Op::Not: s[top - 1] = s[top - 1] == 0.0 ? 1.0 : 0.0; break;
      case Op::Abs: s[top - 1] = std::abs(s[top - 1]); break;
      case Op::Sqrt: s[top - 1] = s[top - 1] > 0.0 ? std::sqrt(s[top - 1]) : 0.0; break;
      case Op::Exp: s[top - 1] = finite(std::exp(s[top - 1])); break;
      case Op::Log: s[top - 1] = s[top - 1] > 0.0 ? std::log(s[top - 1]) : 0.0; break;
      case Op::Tanh: s[top - 1] = std::tanh(s[top - 1]); break;
      case Op::Sigmoid: s[top - 1] = 1.0 / (1.0 + std::exp(-s[top - 1])); break;
      case Op::Clamp: {
        top -= 2;
        const double lo = s[top], hi = s[top + 1];
        s[top - 1] = std::min(std::max(s[top - 1], lo), hi);
        break;
      }
      case Op::Select: {
        top -= 2;
        s[top - 1] = s[top - 1] != 0.0 ? s[top] : s[top + 1];
        break;
      }
      default: {
        const double b = s[--top];
        double& a = s[top - 1];
        switch (in.op) {
          case Op::Add: a = finite(a + b); break;
          case Op::Sub: a = finite(a - b); break;
          case Op::Mul: a = finite(a * b); break;
          case Op::Div: a = b == 0.0 ? 0.0 : finite(a / b); break;
          case Op::Pow: a = finite(std::pow(a, b)); break;
          case Op::Min: a = std::min(a, b); break;
          case Op::Max: a = std::max(a, b); break;
          case Op::Lt: a = a < b ? 1.0 : 0.0; break;
          case Op::Le: a = a <= b ? 1.0 : 0.0; break;
          case Op::Gt: a = a > b ? 1.0 : 0.0; break;
          case Op::Ge: a = a >= b ? 1.0 : 0.0; break;
          case Op::Eq: a = a == b ? 1.0 : 0.0; break;
          case Op::Ne: a = a != b ? 1.0 : 0.0; break;
          case Op::And: a = (a != 0.0 && b != 0.0) ? 1.0 : 0.0; break;
          case Op::Or: a = (a != 0.0 || b != 0.0) ? 1.0 : 0.0; break;
          default: break;
        }
      }
    }
  }
  return top == 1 ? s[0] : 0.0;
}

std::string Program::disassemble() const {
  std::string out;
  for (const Instr& in : code_) {
    if (!out.empty()) out += ' ';
    out += name_of(in.op);
    if (in.op == Op::Const) out += fmt::format(" {}", in.value);
    if (in.op == Op::Load) out += fmt::format(" {}", in.slot);
  }
  return out;
}

}  // namespace esc::expr
