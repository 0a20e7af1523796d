#pragma once
// A plain recursive tree walker: the reference the flat evaluator is tested against and
// the baseline of the benchmark. Same arithmetic (semantics.hpp), only the chosen branch of
// if-then-else is evaluated. Precondition: the tree is well typed.
#include <span>

#include "runtime/genome/tree/program.hpp"

namespace esc::genome::tree {

[[nodiscard]] Output evaluate_recursive(const Tree& tree, const PrimitiveSet& set,
                                        std::span<const double> frame) noexcept;

// The Number/Bool value of the subtree at node i.
[[nodiscard]] double evaluate_number(const Tree& tree, const PrimitiveSet& set,
                                     std::span<const double> frame, std::size_t i) noexcept;

}  // namespace esc::genome::tree
