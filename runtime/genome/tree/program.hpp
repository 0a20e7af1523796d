#pragma once
// The flat evaluator: a tree compiled once into postfix code over a fixed stack of doubles,
// then run at every control step with no allocation. Operators are those of expr::Program
// with the same arithmetic (semantics.hpp); if-then-else compiles to jumps, so only the
// chosen branch runs (the value is the same as evaluating both: every operator is pure).
// That also makes typed roots cheap: along any path through an Action, Behavior or Wheels
// tree exactly one action, behavior or wheels node runs, and it writes the result
// registers.
//
//   FlatProgram p = compile(tree, set);              // allocates; once per genome
//   FlatProgram::Stack stack;                        // caller-owned scratch, reused
//   Output out = p.run(frame, stack);                // per step, no allocation
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "runtime/genome/tree/tree.hpp"
#include "runtime/expr/observables.hpp"

namespace esc::genome::tree {

// What a tree computes, by root type.
struct Output {
  double value = 0.0;                               // Number or Bool root
  double left = 0.0, right = 0.0;                   // Wheels root (not clamped)
  std::int32_t index = -1;                          // Action or Behavior root
  std::array<double, expr::kMaxParams> params{};    // Action root: its parameters
  std::uint8_t param_count = 0;

  friend bool operator==(const Output&, const Output&) = default;
};

enum class Code : std::uint8_t {
  // The first codes equal expr::Op's, so an Op converts by value (static_asserts in .cpp).
  Const, Load,
  Neg, Not, Abs, Sqrt, Exp, Log, Tanh, Sigmoid,
  Add, Sub, Mul, Div, Pow, Min, Max, Lt, Le, Gt, Ge, Eq, Ne, And, Or,
  Clamp,
  Unused,       // expr::Op::Select: compiled to jumps instead
  JumpIfZero,   // pop c; if c == 0 jump to target
  Jump,         // jump to target
  Action,       // pop `count` parameters; index = arg
  Behavior,     // index = arg
  Wheels,       // pop right, left
};

struct Instr {
  Code code = Code::Const;
  std::uint8_t count = 0;   // Action: parameter count
  std::uint32_t arg = 0;    // Load: slot; jumps: target; Action, Behavior: index
  double value = 0.0;       // Const
};

class FlatProgram {
 public:
  static constexpr std::size_t kMaxStack = 128;
  using Stack = std::array<double, kMaxStack>;

  FlatProgram() = default;

  // Precondition: every Load slot lies inside `frame`.
  [[nodiscard]] Output run(std::span<const double> frame, Stack& stack) const noexcept;
  [[nodiscard]] Output run(std::span<const double> frame) const noexcept {
    Stack s;  // NOLINT: written before read
    return run(frame, s);
  }

  [[nodiscard]] Type type() const noexcept { return type_; }
  [[nodiscard]] std::span<const Instr> code() const noexcept { return code_; }
  [[nodiscard]] std::size_t max_stack() const noexcept { return max_stack_; }
  // One instruction per line, "3: jz 7", for tests and diagnostics.
  [[nodiscard]] std::string disassemble() const;

 private:
  friend FlatProgram compile(const Tree& tree, const PrimitiveSet& set);
  std::vector<Instr> code_;
  Type type_ = Type::Number;
  std::size_t max_stack_ = 0;
};

// Compiles a well-typed tree (of any root type). Throws std::invalid_argument if the tree is
// not well typed for its root's type or needs more than kMaxStack stack slots (only trees
// deeper than GpSettings::kMaxDepthLimit can).
[[nodiscard]] FlatProgram compile(const Tree& tree, const PrimitiveSet& set);

}  // namespace esc::genome::tree
