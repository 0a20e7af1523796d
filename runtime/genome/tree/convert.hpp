#pragma once
// Trees as the expression programs a hand-written script produces: a Number/Bool subtree as
// an expr::Program, and each wheel of a Wheels tree as one (the two programs of the behavior
// the printed tree is; tree_control/tree_behavior.hpp). These are the programs the compiler
// builds from the printed text (print.hpp) up to constant folding, which the compiler does
// with expr::Program's own arithmetic; so they evaluate bit for bit like the tree, and a
// test can show the round trip without a parser.
#include <cstddef>

#include "runtime/genome/tree/tree.hpp"
#include "runtime/expr/program.hpp"

namespace esc::genome::tree {

// Throws std::invalid_argument if node i is not a Number/Bool subtree or the program
// would not fit expr::Program's stack (expr::Program::kMaxStack).
[[nodiscard]] expr::Program to_expr_program(const Tree& tree, const PrimitiveSet& set, std::size_t i);

// Wheel `wheel` (0: left, 1: right) of a Wheels tree, if-then-else over Wheels pushed into
// the wheel as print.hpp prints it. Throws std::invalid_argument if the root is not Wheels
// or the program would not fit expr::Program's stack.
[[nodiscard]] expr::Program to_wheel_program(const Tree& tree, const PrimitiveSet& set, std::size_t wheel);

}  // namespace esc::genome::tree
