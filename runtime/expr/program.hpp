#pragma once
// A compiled expression: a flat postfix program over doubles, evaluated on a fixed-size
// stack with no allocation (the fitness and behavior expressions run at every control
// step). Programs are built by the compiler; every operator is total, so a program never
// yields NaN or infinity from finite inputs: x / 0 is 0, sqrt of a negative number is 0,
// log of a non-positive number is 0. Booleans are 0 and 1; any non-zero value is true.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace esc::expr {

// Where overflow saturates: every arithmetic operator's result is clamped to +-kSaturation,
// and an evaluation's fitness (a sum of step terms) saturates at the same value.
inline constexpr double kSaturation = 1e300;

// a + b saturated at +-kSaturation, as the operators saturate: a sum of step values (an
// evaluation's fitness, a step aggregate's `sum(x)`) that one constant term of 1e308 over
// two steps would otherwise take to infinity. A NaN, which no operator makes (only a broken
// observable could), is the lowest value. Identical to a plain sum within the limits.
[[nodiscard]] inline double saturating_add(double a, double b) noexcept {
  const double s = a + b;
  if (std::isnan(s)) return -kSaturation;
  return std::clamp(s, -kSaturation, kSaturation);
}

enum class Op : std::uint8_t {
  Const,   // push value
  Load,    // push frame[slot]
  Neg, Not, Abs, Sqrt, Exp, Log, Tanh, Sigmoid,                 // unary
  Add, Sub, Mul, Div, Pow, Min, Max, Lt, Le, Gt, Ge, Eq, Ne, And, Or,  // binary
  Clamp,   // x lo hi -> x clamped to [lo, hi]
  Select,  // c a b -> c != 0 ? a : b
};

[[nodiscard]] int arity(Op op) noexcept;

struct Instr {
  Op op = Op::Const;
  std::uint32_t slot = 0;
  double value = 0.0;
};

class Program {
 public:
  static constexpr std::size_t kMaxStack = 64;

  Program() = default;
  static Program constant(double v);

  void push_const(double v);
  void push_load(std::uint32_t slot);
  // Appends an operator; throws std::logic_error if the stack holds too few operands
  // (a compiler bug, never a user error).
  void push_op(Op op);

  // True when the program leaves exactly one value and fits the fixed stack.
  [[nodiscard]] bool complete() const noexcept { return depth_ == 1 && max_depth_ <= kMaxStack; }
  [[nodiscard]] std::size_t max_depth() const noexcept { return max_depth_; }
  [[nodiscard]] std::span<const Instr> code() const noexcept { return code_; }
  [[nodiscard]] bool empty() const noexcept { return code_.empty(); }

  // Precondition: complete(), and every Load slot is inside `frame`.
  [[nodiscard]] double eval(std::span<const double> frame) const noexcept;

  // Postfix listing for diagnostics and tests, e.g. "load 1 const 0 max".
  [[nodiscard]] std::string disassemble() const;

 private:
  std::vector<Instr> code_;
  std::size_t depth_ = 0;
  std::size_t max_depth_ = 0;
};

}  // namespace esc::expr
