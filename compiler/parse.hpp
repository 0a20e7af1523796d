#pragma once
// Script text -> AST. Syntax errors become Diagnostics; declarations that hold one are
// marked `poisoned` so later checks skip them instead of cascading.
#include <filesystem>

#include "compiler/ast.hpp"
#include "compiler/sink.hpp"
#include "compiler/text.hpp"

namespace esc::compiler {

// Deepest nesting of brackets and prefix operators accepted (deeper input is an error,
// never a stack overflow).
inline constexpr int kMaxNesting = 200;

[[nodiscard]] ast::Module parse_module(const CleanText& text, const std::filesystem::path& file, Sink& sink);

}  // namespace esc::compiler
