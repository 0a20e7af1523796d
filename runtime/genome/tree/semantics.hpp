#pragma once
// The arithmetic of GP trees: exactly the semantics of expr::Program (runtime/expr/
// program.cpp), operator by operator, so a tree printed as script code and compiled back
// computes the same doubles bit for bit. Both GP evaluators (flat and recursive) use these
// functions; tests/gp checks them against expr::Program for every operator.
#include <algorithm>
#include <cmath>

#include "runtime/expr/program.hpp"

namespace esc::genome::tree::sem {

// Finite results for finite inputs: overflow saturates, NaN becomes 0 (as expr::Program).
[[nodiscard]] inline double finite(double v) noexcept {
  if (std::isnan(v)) return 0.0;
  return std::clamp(v, -1e300, 1e300);
}

[[nodiscard]] inline double unary(expr::Op op, double x) noexcept {
  using expr::Op;
  switch (op) {
    case Op::Neg: return -x;
    case Op::Not: return x == 0.0 ? 1.0 : 0.0;
    case Op::Abs: return std::abs(x);
    case Op::Sqrt: return x > 0.0 ? std::sqrt(x) : 0.0;
    case Op::Exp: return finite(std::exp(x));
    case Op::Log: return x > 0.0 ? std::log(x) : 0.0;
    case Op::Tanh: return std::tanh(x);
    case Op::Sigmoid: return 1.0 / (1.0 + std::exp(-x));
    default: return 0.0;
  }
}

[[nodiscard]] inline double binary(expr::Op op, double a, double b) noexcept {
  using expr::Op;
  switch (op) {
    case Op::Add: return finite(a + b);
    case Op::Sub: return finite(a - b);
    case Op::Mul: return finite(a * b);
    case Op::Div: return b == 0.0 ? 0.0 : finite(a / b);
    case Op::Pow: return finite(std::pow(a, b));
    case Op::Min: return std::min(a, b);
    case Op::Max: return std::max(a, b);
    case Op::Lt: return a < b ? 1.0 : 0.0;
    case Op::Le: return a <= b ? 1.0 : 0.0;
    case Op::Gt: return a > b ? 1.0 : 0.0;
    case Op::Ge: return a >= b ? 1.0 : 0.0;
    case Op::Eq: return a == b ? 1.0 : 0.0;
    case Op::Ne: return a != b ? 1.0 : 0.0;
    case Op::And: return (a != 0.0 && b != 0.0) ? 1.0 : 0.0;
    case Op::Or: return (a != 0.0 || b != 0.0) ? 1.0 : 0.0;
    default: return 0.0;
  }
}

[[nodiscard]] inline double clamp(double x, double lo, double hi) noexcept {
  return std::min(std::max(x, lo), hi);
}

// A wheel command as control::run_behavior applies it: NaN stops the wheel, else [-1, 1].
[[nodiscard]] inline double wheel(double v) noexcept {
  if (std::isnan(v)) return 0.0;
  return std::clamp(v, -1.0, 1.0);
}

}  // namespace esc::genome::tree::sem
