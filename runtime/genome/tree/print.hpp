#pragma once
// Trees as esc script code (docs/language.md, "Expressions"), to be read and pasted back.
//
// Number and Bool subtrees print as ordinary expressions over observable names:
//   - operators infix with the script's precedences, parentheses only where the parse would
//     otherwise differ: `ir[0] * (ir[1] - 0.5)`, `a - (b - c)`, `(a ^ b) ^ c`, `a ^ (-b)`;
//     unary minus `-x`, `not c`, `a and b`, comparisons `ir[0] > 0.5`;
//   - functions as calls: `min(a, b)`, `max`, `abs`, `sqrt`, `exp`, `log`, `tanh`,
//     `sigmoid`, `clamp(x, lo, hi)`; protected division prints as `/` (the script's `/` is
//     protected too);
//   - if-then-else as `if c then a else b`, parenthesised when it is an operand;
//   - constants in the shortest form that reads back as the same double (`0.1`, `-0.25`,
//     `1e-05`, `3`), Bool constants as `true` / `false`.
// Whole trees by root type:
//   Number, Bool: the expression;
//   Wheels:   `wheels(LEFT, RIGHT)`, a behavior body; an if-then-else over Wheels is pushed
//             into both wheels (`wheels(if c then a else b, if c then d else e)`), which
//             computes the same commands;
//   Action:   `if c then left(0.3) else forward(ir[2])`, an action with its parameters;
//   Behavior: `if ir[0] > 0.5 then avoid else explore`.
// behavior_script() wraps a Wheels tree as `behavior NAME() { wheels(LEFT, RIGHT) }`; the
// compiler turns it into the same expr programs as to_wheel_program() (convert.hpp), so the
// pasted behavior scores exactly the fitness of the tree.
#include <cstddef>
#include <string>
#include <string_view>

#include "runtime/genome/tree/tree.hpp"

namespace esc::genome::tree {

// The Number or Bool subtree at node i.
[[nodiscard]] std::string expression(const Tree& tree, const PrimitiveSet& set, std::size_t i);
// The whole tree, by root type (see above).
[[nodiscard]] std::string to_script(const Tree& tree, const PrimitiveSet& set);
// A Wheels tree as a behavior declaration. Throws std::invalid_argument for other roots.
[[nodiscard]] std::string behavior_script(const Tree& tree, const PrimitiveSet& set,
                                          std::string_view name);
// A double in the shortest form that reads back exactly (negative numbers with a minus).
[[nodiscard]] std::string number_text(double v);

}  // namespace esc::genome::tree
