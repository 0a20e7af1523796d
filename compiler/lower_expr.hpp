#pragma once
// Expressions -> expr::Program: names resolve to frame slots, units to SI, constant
// subexpressions are folded, and a program deeper than the evaluator's stack is an error.
#include <optional>
#include <string>
#include <vector>

#include "compiler/ast.hpp"
#include "compiler/sink.hpp"
#include "runtime/expr/program.hpp"

namespace esc::compiler {

// The zones and lights of an experiment's arena, in declaration order: `in(zone)` and
// `reached(light)` read slot first + index.
struct ArenaNames {
  std::string arena;                 // the arena's name, for messages
  std::vector<std::string> zones, lights;
};

struct ExprScope {
  std::vector<std::string> params;   // behavior parameters, read from slot::param + i
  // The arena `in(...)` / `reached(...)` resolve in. Null outside an experiment: then their
  // argument is only checked to be a name (each experiment lowers the expression again with
  // its arena).
  const ArenaNames* arena = nullptr;
};

// Reports errors to `sink`; nullopt when the expression has one.
[[nodiscard]] std::optional<expr::Program> lower_expr(const ast::Expr& e, const ExprScope& scope, Sink& sink);

// The script functions with their arity ("min" -> 2, ...), for docs and suggestions.
[[nodiscard]] std::vector<std::string> function_names();

}  // namespace esc::compiler
