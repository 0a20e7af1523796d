#pragma once
// Trees as the runtime objects a hand-written script produces: a Number/Bool subtree as an
// expr::Program, a Wheels tree as a control::Behavior. These are the programs the compiler
// builds from the printed text (print.hpp) up to constant folding, which the compiler does
// with expr::Program's own arithmetic; so they evaluate bit for bit like the tree, and a
// test can show the round trip without a parser.
#include <string>

#include "runtime/control/behavior.hpp"
#include "runtime/evo/gp/tree.hpp"
#include "runtime/expr/program.hpp"

namespace esc::evo::gp {

// Throws std::invalid_argument if node i is not a Number/Bool subtree or the program
// would not fit expr::Program's stack (expr::Program::kMaxStack).
[[nodiscard]] expr::Program to_expr_program(const Tree& tree, const PrimitiveSet& set, std::size_t i);

// A Wheels tree as a behavior with no parameters (if-then-else over Wheels pushed into
// both wheels, as print.hpp prints it).
[[nodiscard]] control::Behavior to_behavior(const Tree& tree, const PrimitiveSet& set,
                                            std::string name);

}  // namespace esc::evo::gp
